// Ray/primitive intersection. Rays have unit directions; all tests return the hit distance t.

#define kInfinity uintBitsToFloat(0x7F800000u)

// Numerically stable ray/sphere test (Haines et al., Ray Tracing Gems ch. 7): the discriminant
// from the distance of the centre to the ray line, the roots via q to avoid cancellation.
bool intersectSphere(vec3 origin, vec3 dir, vec4 centerRadius, float tMax, out float t) {
    vec3 oc = origin - centerRadius.xyz;
    float b = dot(oc, dir);
    vec3 closest = oc - b * dir;
    float r2 = centerRadius.w * centerRadius.w;
    float disc = r2 - dot(closest, closest);
    if (disc < 0.0)
        return false;
    float root = sqrt(disc);
    float q = b > 0.0 ? -(b + root) : -(b - root);
    float c = dot(oc, oc) - r2;
    float t0 = q != 0.0 ? c / q : 0.0;
    float t1 = q;
    float near = min(t0, t1), far = max(t0, t1);
    t = near > 0.0 ? near : far;
    return t > 0.0 && t < tMax;
}

bool intersectPlane(vec3 origin, vec3 dir, vec4 normalOffset, float tMax, out float t) {
    float denom = dot(normalOffset.xyz, dir);
    if (denom == 0.0)
        return false;
    t = (normalOffset.w - dot(normalOffset.xyz, origin)) / denom;
    return t > 0.0 && t < tMax;
}

// Per-ray constants of the watertight test (Woop, Benthin & Wald 2013): the axis of largest
// |dir| becomes z, the others are sheared so the ray runs along +z.
struct WatertightRay {
    ivec3 k;     // kx, ky, kz
    vec3 shear;  // Sx, Sy, Sz
};

WatertightRay makeWatertightRay(vec3 dir) {
    vec3 a = abs(dir);
    int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (dir[kz] < 0.0) { int tmp = kx; kx = ky; ky = tmp; } // keep the winding
    WatertightRay r;
    r.k = ivec3(kx, ky, kz);
    r.shear = vec3(dir[kx] / dir[kz], dir[ky] / dir[kz], 1.0 / dir[kz]);
    return r;
}

// a * b - c * d with the sign of the exact value (Kahan's difference of products: fma recovers
// the rounding error of c * d exactly and adds it back; relative error at most 2 ulp,
// Jeannerod, Louvet & Muller 2013). `precise` keeps the compiler from folding the recovery.
float differenceOfProducts(float a, float b, float c, float d) {
    precise float cd = c * d;
    precise float error = fma(-c, d, cd);
    precise float ab = fma(a, b, -cd);
    precise float result = ab + error;
    return result;
}

// Watertight ray/triangle test: edge functions U, V, W exact in sign, so a ray through a shared
// edge or vertex hits one of the triangles (the CPU reference computes them in double).
bool intersectTriangle(vec3 origin, WatertightRay r, vec3 p0, vec3 p1, vec3 p2, float tMax,
                       out float t, out vec2 b12) {
    vec3 a = p0 - origin, b = p1 - origin, c = p2 - origin;
    float ax = a[r.k.x] - r.shear.x * a[r.k.z], ay = a[r.k.y] - r.shear.y * a[r.k.z];
    float bx = b[r.k.x] - r.shear.x * b[r.k.z], by = b[r.k.y] - r.shear.y * b[r.k.z];
    float cx = c[r.k.x] - r.shear.x * c[r.k.z], cy = c[r.k.y] - r.shear.y * c[r.k.z];
    float u = differenceOfProducts(cx, by, cy, bx);
    float v = differenceOfProducts(ax, cy, ay, cx);
    float w = differenceOfProducts(bx, ay, by, ax);
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0))
        return false;
    float det = u + v + w;
    if (det == 0.0)
        return false;
    float az = r.shear.z * a[r.k.z], bz = r.shear.z * b[r.k.z], cz = r.shear.z * c[r.k.z];
    float tScaled = u * az + v * bz + w * cz;
    float invDet = 1.0 / det;
    t = tScaled * invDet;
    b12 = vec2(v, w) * invDet;
    return t > 0.0 && t < tMax;
}

// The common ray/triangle test (Moller & Trumbore 1997), kept for the triangles study only: its
// edge tests round differently on the two triangles of a shared edge, so a ray through the edge
// can miss both. Same outputs as intersectTriangle (b12: barycentrics of p1 and p2).
bool intersectTriangleMollerTrumbore(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2,
                                     float tMax, out float t, out vec2 b12) {
    vec3 e1 = p1 - p0, e2 = p2 - p0;
    vec3 p = cross(dir, e2);
    float det = dot(e1, p);
    if (det == 0.0)
        return false;
    float invDet = 1.0 / det;
    vec3 s = origin - p0;
    float u = dot(s, p) * invDet;
    if (u < 0.0 || u > 1.0)
        return false;
    vec3 q = cross(s, e1);
    float v = dot(dir, q) * invDet;
    if (v < 0.0 || u + v > 1.0)
        return false;
    t = dot(e2, q) * invDet;
    b12 = vec2(u, v);
    return t > 0.0 && t < tMax;
}
