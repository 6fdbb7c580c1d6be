// Lets one header be compiled as C++ (host, CPU reference) and as GLSL (tracer).
#ifndef PRISM_GLSL_COMPAT_H
#define PRISM_GLSL_COMPAT_H
#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace prism::gpu {
using uint = uint32_t;
using vec2 = glm::vec2;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
} // namespace prism::gpu
#define PRISM_NAMESPACE_BEGIN namespace prism::gpu {
#define PRISM_NAMESPACE_END }
#define PRISM_INLINE inline
#else
#define PRISM_NAMESPACE_BEGIN
#define PRISM_NAMESPACE_END
#define PRISM_INLINE
#endif
#endif
