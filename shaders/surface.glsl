// What a hit looks like to the shader: position, normals, texture coordinates, material.

const float kPi = 3.14159265358979323846;

struct Surface {
    vec3 position;
    vec3 geometricNormal; // the primitive's own normal (sphere outward, plane given, triangle ABC)
    vec3 shadingNormal;   // interpolated vertex normal where present, else geometricNormal
    vec2 uv;
    uint material;
    // Where shadow rays leave from (reference: surface_reference.h, smoothSurfacePoint):
    // position, or on the front of a triangle with vertex normals the smooth surface's point.
    vec3 shadowPosition;
    bool smoothed; // vertex normals: shadow rays take the shading normal's horizon
    // Directions of increasing u and v on the surface (any length), for the tangent frame of
    // normal and bump maps (surface_maps.glsl); set only where HAS_SURFACE_MAPS.
    vec3 dpdu;
    vec3 dpdv;
    // An instance's triangle is known only as well as its placement: in the prototype's space
    // (where the walk tests it) its points are floats of magnitude |v|, so in the scene its error
    // grows with scale * |v|, however near the camera the hit is. Ray offsets take this as a
    // floor for max|P| (offsetOrigin); 0 for everything else.
    float offsetFloor;
};

// Hanika 2021 (surface_reference.h): p lifted onto each vertex's tangent plane where below it,
// blended by the barycentrics.
vec3 smoothSurfacePoint(vec3 p, vec3 p0, vec3 p1, vec3 p2, vec3 n0, vec3 n1, vec3 n2, vec3 b) {
    return b.x * (p - min(0.0, dot(p - p0, n0)) * n0) + b.y * (p - min(0.0, dot(p - p1, n1)) * n1) +
           b.z * (p - min(0.0, dot(p - p2, n2)) * n2);
}

// Plane texture axes: a1 = normalize(n x e) with e the world axis least aligned with n
// (x before y before z on ties), a2 = n x a1.
vec3 planeAxisU(vec3 n) {
    vec3 a = abs(n);
    vec3 axis = (a.x <= a.y && a.x <= a.z) ? vec3(1, 0, 0)
                                           : (a.y <= a.z ? vec3(0, 1, 0) : vec3(0, 0, 1));
    return normalize(cross(n, axis));
}
vec2 planeUV(vec3 p, vec3 n) {
    vec3 a1 = planeAxisU(n);
    return vec2(dot(p, a1), dot(p, cross(n, a1)));
}

// dp/du and dp/dv of a triangle from its corners' texture coordinates (Lengyel's tangent
// formula), each times sign(det) rather than divided by det: only their directions are used,
// and a triangle whose UVs have no area (det 0) gives zero vectors, so the tangent frame falls
// back to its arbitrary one (surface_maps.glsl).
void triangleTangents(vec3 e1, vec3 e2, vec2 d1, vec2 d2, out vec3 dpdu, out vec3 dpdv) {
    float det = d1.x * d2.y - d1.y * d2.x;
    dpdu = sign(det) * (d2.y * e1 - d1.y * e2);
    dpdv = sign(det) * (d1.x * e2 - d2.x * e1);
}

// An instance's map out of its prototype's space (rows of GpuInstance::toWorld): a similarity,
// so normals turn as positions do and only need normalising.
vec3 placePoint(vec4 rows[3], vec3 p) {
    return vec3(dot(rows[0].xyz, p) + rows[0].w, dot(rows[1].xyz, p) + rows[1].w,
                dot(rows[2].xyz, p) + rows[2].w);
}
vec3 placeNormal(vec4 rows[3], vec3 n) {
    return normalize(vec3(dot(rows[0].xyz, n), dot(rows[1].xyz, n), dot(rows[2].xyz, n)));
}

// Hit points are rebuilt from the primitive (not origin + t * dir) so their error is relative
// to |P|, which is what the relative ray offset assumes.
Surface surfaceAt(vec3 origin, vec3 dir, Hit hit) {
    Surface s;
    s.offsetFloor = 0.0;
#ifndef PRISM_PLANES_ONLY // (its module has planes only: trace_bindings.glsl)
    if (HAS_SPHERES && hit.kind == kKindSphere) {
        GpuSphere sphere = sphereAt(hit.index);
        vec4 cr = sphere.centerRadius;
        vec3 n = normalize(origin + hit.t * dir - cr.xyz);
        s.position = cr.xyz + cr.w * n;
        s.geometricNormal = n;
        s.shadingNormal = n;
        s.shadowPosition = s.position;
        s.smoothed = false;
        s.uv = vec2(0.5 + atan(n.z, n.x) / (2.0 * kPi), 0.5 + asin(clamp(n.y, -1.0, 1.0)) / kPi);
        if (HAS_SURFACE_MAPS) { // u turns with atan2(z, x), v climbs with asin(y); 0 at poles
            s.dpdu = vec3(-n.z, 0.0, n.x);
            s.dpdv = vec3(-n.y * n.x, n.x * n.x + n.z * n.z, -n.y * n.z);
        }
        s.material = sphereMaterial(sphere);
    } else
#endif
    if (HAS_PLANES && hit.kind == kKindPlane) {
        GpuPlane plane = planeAt(hit.index);
        vec4 no = plane.normalOffset;
        vec3 p = origin + hit.t * dir;
        s.position = p - (dot(no.xyz, p) - no.w) * no.xyz;
        s.geometricNormal = no.xyz;
        s.shadingNormal = no.xyz;
        s.shadowPosition = s.position;
        s.smoothed = false;
        s.uv = (HAS_TEXTURES || HAS_SURFACE_MAPS) ? planeUV(s.position, no.xyz) : vec2(0.0);
        if (HAS_SURFACE_MAPS) {
            s.dpdu = planeAxisU(no.xyz);
            s.dpdv = cross(no.xyz, s.dpdu);
        }
        s.material = planeMaterial(plane);
    }
#ifndef PRISM_PLANES_ONLY
    else {
        GpuTriangle tri = triangleAt(hit.index);
        bool instanced = HAS_INSTANCES && hit.instance != kNoInstance;
        vec4 toWorld[3];
        if (instanced) { // the prototype's triangle, placed: then all is as for the scene's own
            for (uint r = 0u; r < 3u; ++r)
                toWorld[r] = instanceRow(hit.instance, 3u + r);
            vec3 m = max(abs(tri.v0.xyz), max(abs(tri.v1.xyz), abs(tri.v2.xyz)));
            s.offsetFloor = length(toWorld[0].xyz) * max(m.x, max(m.y, m.z)); // scale * max|v|
            tri.v0.xyz = placePoint(toWorld, tri.v0.xyz);
            tri.v1.xyz = placePoint(toWorld, tri.v1.xyz);
            tri.v2.xyz = placePoint(toWorld, tri.v2.xyz);
        }
        float b1 = hit.b12.x, b2 = hit.b12.y, b0 = 1.0 - b1 - b2;
        s.position = b0 * tri.v0.xyz + b1 * tri.v1.xyz + b2 * tri.v2.xyz;
        s.geometricNormal = normalize(cross(tri.v1.xyz - tri.v0.xyz, tri.v2.xyz - tri.v0.xyz));
        s.shadingNormal = s.geometricNormal;
        s.uv = vec2(b1, b2);
        s.shadowPosition = s.position;
        s.smoothed = false;
        // Without texture coordinates (u, v) = (b1, b2): corners (0, 0), (1, 0), (0, 1).
        vec2 d1 = vec2(1.0, 0.0), d2 = vec2(0.0, 1.0);
        if (HAS_VERTEX_NORMALS || HAS_TEXTURES || HAS_SURFACE_MAPS) {
            GpuTriangleShading sh = triangleShadingAt(hit.index);
            if (HAS_VERTEX_NORMALS && shadingHasNormals(sh)) {
                if (instanced) {
                    sh.n0.xyz = placeNormal(toWorld, sh.n0.xyz);
                    sh.n1.xyz = placeNormal(toWorld, sh.n1.xyz);
                    sh.n2.xyz = placeNormal(toWorld, sh.n2.xyz);
                }
                s.shadingNormal = normalize(b0 * sh.n0.xyz + b1 * sh.n1.xyz + b2 * sh.n2.xyz);
                s.smoothed = true;
                if (dot(dir, s.geometricNormal) < 0.0)
                    s.shadowPosition =
                        smoothSurfacePoint(s.position, tri.v0.xyz, tri.v1.xyz, tri.v2.xyz,
                                           sh.n0.xyz, sh.n1.xyz, sh.n2.xyz, vec3(b0, b1, b2));
            }
            if ((HAS_TEXTURES || HAS_SURFACE_MAPS) && shadingHasUVs(sh)) {
                s.uv = b0 * sh.uv01.xy + b1 * sh.uv01.zw + b2 * sh.uv2.xy;
                d1 = sh.uv01.zw - sh.uv01.xy;
                d2 = sh.uv2.xy - sh.uv01.xy;
            }
        }
        if (HAS_SURFACE_MAPS)
            triangleTangents(tri.v1.xyz - tri.v0.xyz, tri.v2.xyz - tri.v0.xyz, d1, d2, s.dpdu,
                             s.dpdv);
        s.material = triangleMaterial(tri);
        vec4 info = instanced ? instanceRow(hit.instance, 6u) : vec4(0.0);
        if (instanced && instanceOverridesMaterial(info)) // the placement's material
            s.material = instanceMaterial(info);
    }
#endif
    return s;
}

// Bilinear lookup with wrap-around; v = 0 is the image's bottom row, texels are stored top row
// first.
vec3 textureColor(uint textureIndex, vec2 uv) {
    GpuTexture texture = textureAt(textureIndex);
    int w = int(textureWidth(texture)), h = int(textureHeight(texture));
    uint first = textureFirstTexel(texture);
    vec2 xy = vec2(uv.x * float(w), uv.y * float(h)) - 0.5;
    vec2 base = floor(xy);
    vec2 f = xy - base;
    // Floor-modulo in float: int() of a huge coordinate would be undefined.
    int x0 = clamp(int(base.x - float(w) * floor(base.x / float(w))), 0, w - 1);
    int y0 = clamp(int(base.y - float(h) * floor(base.y / float(h))), 0, h - 1);
    int x1 = (x0 + 1) % w, y1 = (y0 + 1) % h;
    // Bottom-based rows map to stored rows h-1-y.
    uint rowA = uint(h - 1 - y0) * uint(w), rowB = uint(h - 1 - y1) * uint(w);
    vec4 c00 = textureTexel(first + rowA + uint(x0)), c10 = textureTexel(first + rowA + uint(x1));
    vec4 c01 = textureTexel(first + rowB + uint(x0)), c11 = textureTexel(first + rowB + uint(x1));
    return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y).rgb;
}

// Offset origin for a ray leaving `position` in `dir`: along the facing geometric normal, by an
// amount relative to max|P_i| (never a fixed epsilon), or to the surface's offsetFloor where
// that is larger (an instance's). FIXED_RAY_OFFSET > 0 is the original's fixed epsilon, kept
// for the offsets study only.
vec3 offsetOrigin(vec3 position, float offsetFloor, vec3 facingNormal, vec3 dir) {
    vec3 a = abs(position);
    float magnitude = max(max(a.x, max(a.y, a.z)), HAS_INSTANCES ? offsetFloor : 0.0);
    float eps = max(magnitude, float(PRISM_OFFSET_FLOOR)) * float(PRISM_OFFSET_RELATIVE);
    if (FIXED_RAY_OFFSET > 0.0)
        eps = FIXED_RAY_OFFSET;
    return position + (dot(dir, facingNormal) >= 0.0 ? eps : -eps) * facingNormal;
}

// What a ray that misses everything sees: the lat-long environment where the scene has one
// (docs/scene-format.md), else the background. u turns with atan2(x, -z) less the rotation, so
// the image's centre lies along -z; v from asin(y), held half a texel from the poles so that
// bilinear filtering does not wrap from the top row to the bottom one.
vec3 missColor(vec3 dir) {
    if (!HAS_ENVIRONMENT)
        return header.background.rgb;
    vec4 e = header.environment;
    uint index = uint(e.x);
    vec3 d = normalize(dir);
    float u = 0.5 + (atan(d.x, -d.z) - e.z) / (2.0 * kPi);
    float v = 0.5 + asin(clamp(d.y, -1.0, 1.0)) / kPi;
    float halfTexel = 0.5 / float(textureHeight(textureAt(index)));
    return e.y * textureColor(index, vec2(u, clamp(v, halfTexel, 1.0 - halfTexel)));
}
