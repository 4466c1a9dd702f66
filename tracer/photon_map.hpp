// The photon map (POV-Ray 3.7's PhotonMap and PhotonGatherer,
// source/core/lighting/photons.cpp; Jensen, "Realistic Image Synthesis
// Using Photon Mapping", 2001): the photons a frame's shooting left on
// surfaces, in a balanced kd-tree kept in the array itself (the element in
// the middle of a range splits it along the axis its photons spread most
// on), and the gather that finds the nearest ones around a point, within
// a disc flattened along the surface's normal, with POV-Ray's adaptive
// radius.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/scene/photon_settings.hpp"

namespace hexant::tracer {

// One photon: where it landed, the light it carries there (POV-Ray's
// LightCol2: the light's colour times what the path let through, the area
// a photon stands for (spacing squared, times the distance squared for a
// light that is not parallel) and the light's fade compensation), the unit
// direction back toward where it came from, and when it was shot. Single
// precision, as POV-Ray stores photons (a photon's place and direction
// are a gather's approximations anyway).
struct Photon {
    glm::vec3 position{0.0f};
    glm::vec3 colour{0.0f};
    glm::vec3 from{0.0f};
    float time = 0.0f;
    std::uint8_t axis = 0;  // the kd-tree's split at this element
};

class PhotonMap {
  public:
    PhotonMap() = default;
    // A map of the photons left on surfaces, or of those left in media
    // along their way (POV-Ray's mediaPhotonMap): its density is per
    // volume, its gathers spheres.
    enum class Kind { Surface, Media };
    // Takes the photons and builds the tree; then, as POV-Ray's
    // setGatherOptions, the gather radius: `settings.radius` (for media,
    // `media_radius`) when given, else from the map's mean density (per
    // area, or per volume for media) so that a gather meets about
    // gather_max photons (widened where many gathers find less than 70%
    // of the mean), times `radius_factor` (`media_radius_factor`).
    PhotonMap(std::vector<Photon> photons, const runtime::PhotonSettings& settings,
              Kind kind = Kind::Surface);

    std::size_t size() const { return photons_.size(); }
    bool empty() const { return photons_.empty(); }
    double radius() const { return radius_; }

    // The photons around `point` on a surface whose normal is `normal`
    // (unit), POV-Ray's gatherPhotonsAdaptive: the nearest gather_max
    // within the radius (distances stretched across the surface: squared
    // distance times 1 + 16 |normal . offset|, POV-Ray's flattening), and
    // where fewer than gather_min are found, once more within three times
    // the radius if the density holds (expand_thresholds). `out` receives
    // them with their stretched squared distances, in no order (it keeps
    // its capacity: a caller reusing it allocates nothing once warm);
    // returns the radius their estimate divides by (the farthest kept's
    // distance when gather_max were kept, else the search radius).
    using Found = std::vector<std::pair<double, const Photon*>>;
    double gather(const glm::dvec3& point, const glm::dvec3& normal, Found& out) const {
        return gather(point, &normal, out);
    }
    // The same within a sphere (a media map's gather: POV-Ray's
    // ComputeMediaPhotons passes no normal).
    double gather_in_volume(const glm::dvec3& point, Found& out) const {
        return gather(point, nullptr, out);
    }

  private:
    double gather(const glm::dvec3& point, const glm::dvec3* normal, Found& out) const;
    // The nearest `most` within `size` (squared distances, stretched);
    // returns the radius as POV-Ray's gatherPhotons.
    double gather_within(const glm::dvec3& point, const glm::dvec3* normal, double size, int most,
                         std::vector<std::pair<double, const Photon*>>& heap) const;
    void build(std::size_t begin, std::size_t end);

    std::vector<Photon> photons_;
    runtime::PhotonSettings settings_;
    double radius_ = 0.0;
};

}  // namespace hexant::tracer
