#include "reference/intersect_reference.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace prism::reference {

PlaneEquation planeEquation(const Plane &plane) {
    // The parser stores unit normals; normalising again in double only removes float rounding.
    glm::dvec3 n = glm::normalize(glm::dvec3(plane.normal));
    return {n, glm::dot(n, glm::dvec3(plane.point))};
}

bool intersectSphere(const Ray &ray, glm::dvec3 center, double radius, double tMax, double &t) {
    // Discriminant from the centre's distance to the ray line; roots through q so neither
    // suffers cancellation.
    glm::dvec3 oc = ray.origin - center;
    double b = glm::dot(oc, ray.dir);
    glm::dvec3 closest = oc - b * ray.dir;
    double r2 = radius * radius;
    double disc = r2 - glm::dot(closest, closest);
    if (disc < 0.0)
        return false;
    double root = std::sqrt(disc);
    double q = b > 0.0 ? -(b + root) : -(b - root);
    double c = glm::dot(oc, oc) - r2;
    double t0 = q != 0.0 ? c / q : 0.0;
    double t1 = q;
    double nearT = std::min(t0, t1), farT = std::max(t0, t1);
    t = nearT > 0.0 ? nearT : farT;
    return t > 0.0 && t < tMax;
}

bool intersectPlane(const Ray &ray, const PlaneEquation &plane, double tMax, double &t) {
    double denom = glm::dot(plane.normal, ray.dir);
    if (denom == 0.0)
        return false;
    t = (plane.offset - glm::dot(plane.normal, ray.origin)) / denom;
    return t > 0.0 && t < tMax;
}

WatertightRay makeWatertightRay(glm::dvec3 dir) {
    glm::dvec3 a = glm::abs(dir);
    int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (dir[kz] < 0.0)
        std::swap(kx, ky); // keep the winding
    return {kx, ky, kz, glm::dvec3(dir[kx] / dir[kz], dir[ky] / dir[kz], 1.0 / dir[kz])};
}

bool intersectTriangle(const Ray &ray, const WatertightRay &r, glm::dvec3 p0, glm::dvec3 p1,
                       glm::dvec3 p2, double tMax, double &t, glm::dvec2 &b12) {
    glm::dvec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;
    double ax = a[r.kx] - r.shear.x * a[r.kz], ay = a[r.ky] - r.shear.y * a[r.kz];
    double bx = b[r.kx] - r.shear.x * b[r.kz], by = b[r.ky] - r.shear.y * b[r.kz];
    double cx = c[r.kx] - r.shear.x * c[r.kz], cy = c[r.ky] - r.shear.y * c[r.kz];
    // Scaled barycentrics as 2D edge functions. The shader retries in double when one is
    // exactly zero; here they already are double.
    double u = cx * by - cy * bx;
    double v = ax * cy - ay * cx;
    double w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0))
        return false;
    double det = u + v + w;
    if (det == 0.0)
        return false;
    double az = r.shear.z * a[r.kz], bz = r.shear.z * b[r.kz], cz = r.shear.z * c[r.kz];
    double tScaled = u * az + v * bz + w * cz;
    double invDet = 1.0 / det;
    t = tScaled * invDet;
    b12 = glm::dvec2(v, w) * invDet;
    return t > 0.0 && t < tMax;
}

} // namespace prism::reference
