#include "runtime/motion/deformation.hpp"

namespace hexant::runtime {

namespace {

// F J_local F^T, F's columns the frame's axis, spine and cross.
glm::dmat3 to_object_frame(const glm::dmat3& local, const DeformationFrame<double>& f) {
    const glm::dmat3 frame(glm::dvec3(f.axis[0], f.axis[1], f.axis[2]),
                           glm::dvec3(f.spine[0], f.spine[1], f.spine[2]),
                           glm::dvec3(f.cross[0], f.cross[1], f.cross[2]));
    return frame * local * glm::transpose(frame);
}

// glm builds matrices column by column; these take rows, as written on paper.
glm::dmat3 from_rows(const glm::dvec3& r0, const glm::dvec3& r1, const glm::dvec3& r2) {
    return glm::transpose(glm::dmat3(r0, r1, r2));
}

}  // namespace

glm::dmat3 twist_jacobian(const glm::dvec3& p, const DeformationFrame<double>& f, double amount) {
    const auto q = to_local(std::array<double, 3>{p.x, p.y, p.z}, f);
    const double k = amount * deformation_detail::kDegree;
    const double angle = k * q[0];
    const double cs = std::cos(angle), sn = std::sin(angle);
    const double s = q[1] * cs - q[2] * sn, c = q[1] * sn + q[2] * cs;
    return to_object_frame(from_rows({1.0, 0.0, 0.0}, {-k * c, cs, -sn}, {k * s, sn, cs}), f);
}

glm::dmat3 taper_jacobian(const glm::dvec3& p, const DeformationFrame<double>& f, double amount) {
    const auto q = to_local(std::array<double, 3>{p.x, p.y, p.z}, f);
    const double factor = 1.0 + amount * q[0];
    return to_object_frame(
        from_rows({1.0, 0.0, 0.0}, {amount * q[1], factor, 0.0}, {amount * q[2], 0.0, factor}), f);
}

// d(a S(θ))/da = d(sin(k a) / k)/da = cosθ, d(a C(θ))/da = sinθ.
glm::dmat3 bend_jacobian(const glm::dvec3& p, const DeformationFrame<double>& f, double amount) {
    const auto q = to_local(std::array<double, 3>{p.x, p.y, p.z}, f);
    const double k = amount * deformation_detail::kDegree;
    const double theta = k * q[0];
    const double cs = std::cos(theta), sn = std::sin(theta);
    const double r = 1.0 - k * q[1];
    return to_object_frame(from_rows({r * cs, -sn, 0.0}, {r * sn, cs, 0.0}, {0.0, 0.0, 1.0}), f);
}

}  // namespace hexant::runtime
