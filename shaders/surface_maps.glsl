// Normal and bump maps: the shading normal bent by a material's maps (docs/scene-format.md,
// "Normal and bump maps"; reference: engine/reference/surface_maps_reference.cpp). Only the
// shading normal changes; ray offsets and the shadow horizon keep the unmapped normals.

// Orthonormal frame (t, b, n) for unit n: t is dp/du made orthogonal to n (Gram-Schmidt), and
// b = n x t turned towards dp/dv, so a mirrored UV layout keeps +y = +v. Where dp/du is zero or
// along n (UVs without area, a sphere's pole) t is the plane texture axis of n instead: any
// frame is as good as another there, and this one is defined and finite.
void tangentFrame(vec3 n, vec3 dpdu, vec3 dpdv, out vec3 t, out vec3 b) {
    vec3 along = dpdu - dot(dpdu, n) * n;
    float len = length(along);
    if (len > 1e-6 * length(dpdu)) {
        t = along / len;
        b = cross(n, t);
        if (dot(b, dpdv) < 0.0)
            b = -b;
    } else {
        t = planeAxisU(n);
        b = cross(n, t);
    }
}

// Rec. 709 luminance: a bump map's height, read as data (grey images give their grey).
float bumpHeight(uint map, vec2 uv) {
    return dot(textureColor(map, uv), vec3(0.2126, 0.7152, 0.0722));
}

// dh/du and dh/dv in texture-coordinate units, by central differences one texel either side
// (each difference spans two texels of the bilinear height).
vec2 bumpSlope(uint map, vec2 uv) {
    GpuTexture texture = textureAt(map);
    vec2 size = vec2(float(textureWidth(texture)), float(textureHeight(texture)));
    vec2 texel = 1.0 / size;
    float du = bumpHeight(map, uv + vec2(texel.x, 0.0)) - bumpHeight(map, uv - vec2(texel.x, 0.0));
    float dv = bumpHeight(map, uv + vec2(0.0, texel.y)) - bumpHeight(map, uv - vec2(0.0, texel.y));
    return vec2(du, dv) * size * 0.5;
}

// The shading normal with m's maps applied, in tangent space (t, b, n): a normal map gives
// 2 rgb - 1 (OpenGL convention, +y = +v), else (0, 0, 1); a bump map's slopes times its
// multiplier are taken from x and y (Blinn 1978: the normal of the surface lifted by that
// height along n leans away from uphill). Unit length; n itself if the result has none.
vec3 mappedNormal(Surface s, GpuMaterial m) {
    vec3 n = s.shadingNormal;
    bool normalMap = materialHasNormalMap(m), bumpMap = materialHasBumpMap(m);
    if (!normalMap && !bumpMap)
        return n;
    vec3 t, b;
    tangentFrame(n, s.dpdu, s.dpdv, t, b);
    vec3 local = normalMap ? 2.0 * textureColor(materialNormalMap(m), s.uv) - 1.0 : vec3(0, 0, 1);
    if (bumpMap)
        local.xy -= materialBumpScale(m) * bumpSlope(materialBumpMap(m), s.uv);
    vec3 mapped = local.x * t + local.y * b + local.z * n;
    float len = length(mapped);
    return len > 0.0 ? mapped / len : n; // also n for a NaN length
}
