#version 460
// Shows the tracer's accumulation image: the sum of N samples (alpha counts them) divided by
// N, clamped to [0, 1] and sRGB-encoded; row 0 = top in both images. The image is the
// framebuffer's size (one traced pixel per pixel) or, while the viewer's camera moves, a
// fraction of it, shown by nearest-neighbour magnification. Encoding is the hardware's on an
// *_SRGB swapchain, this shader's otherwise.
layout(constant_id = 0) const bool ENCODE_SRGB = false;

layout(set = 0, binding = 0, rgba32f) uniform readonly image2D accumImage;
layout(push_constant) uniform Present {
    vec2 imagePerFragment; // image size / framebuffer size
} present;
layout(location = 0) out vec4 outColor;

// IEC 61966-2-1, as engine/io/srgb.h (the PNG writer) encodes.
vec3 srgbEncode(vec3 linear) {
    vec3 low = 12.92 * linear;
    vec3 high = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}

void main() {
    ivec2 last = imageSize(accumImage) - 1;
    ivec2 pixel = min(ivec2(gl_FragCoord.xy * present.imagePerFragment), last);
    vec4 sum = imageLoad(accumImage, pixel);
    vec3 colour = clamp(sum.rgb / max(sum.a, 1.0), 0.0, 1.0);
    if (isnan(colour.r) || isnan(colour.g) || isnan(colour.b))
        colour = vec3(0.0);
    outColor = vec4(ENCODE_SRGB ? srgbEncode(colour) : colour, 1.0);
}
