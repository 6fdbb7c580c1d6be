// Lets one header be compiled as C++ (host, CPU reference) and as GLSL (tracer).
#ifndef PRISM_GLSL_COMPAT_H
#define PRISM_GLSL_COMPAT_H
#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace prism::gpu {
using uint = uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec3 = glm::ivec3;
using uvec2 = glm::uvec2;
using uvec4 = glm::uvec4;
} // namespace prism::gpu
#define PRISM_NAMESPACE_BEGIN namespace prism::gpu {
#define PRISM_NAMESPACE_END }
#define PRISM_INLINE inline
// A named constant both languages see (GLSL accepts it in layout(binding = ...) too).
#define PRISM_CONST(type, name, value) inline constexpr type name = value
// A read-only parameter: by const reference in C++, by value in GLSL.
#define PRISM_IN(type) const type &
#else
#define PRISM_NAMESPACE_BEGIN
#define PRISM_NAMESPACE_END
#define PRISM_INLINE
#define PRISM_CONST(type, name, value) const type name = value
#define PRISM_IN(type) type
#endif
#endif
