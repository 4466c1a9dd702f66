// Radiosity's irradiance cache, as POV-Ray 3.7 keeps and reuses it (Ward,
// Rubinstein and Clear, "A ray tracing solution for diffuse
// interreflection", SIGGRAPH 1988; POV-Ray's core/lighting/radiosity.cpp,
// RadiosityCache::FindReusableBlock and AverageNearBlock): each record is
// the light gathered at one point about one normal, with the harmonic mean
// distance of what its rays met; a point nearby reuses the records whose
// error, distance over that mean plus the normals' difference, is within
// the error bound, weighted by how far within.
//
// A frame's cache is filled pass by pass (the pretrace) and only read
// between passes: records gathered during a pass are added after it, in an
// order that does not depend on the threads (tracer/radiosity_pretrace.cpp),
// so that a frame is the same image whatever the threads.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace hexant::tracer {

struct RadiosityRecord {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};       // unit: the normal it gathered about
    glm::dvec3 to_nearest{0.0};   // unit: toward the nearest surface its rays met
    glm::dvec3 illuminance{0.0};  // the gathered rays' mean colour (before brightness)
    double harmonic_mean = 0.0;   // of its rays' distances, clamped by the reuse limits
    double nearest = 0.0;         // the nearest distance its rays met
    double quality = 1.0;
    double brilliance = 1.0;
    int depth = 0;  // its bounce (recursion depth)
};

// One reuse question: a point, its normal, its bounce, the error bound,
// and whether the smooth (pseudo-sigmoid) weight applies: POV-Ray's final
// trace at bounce 0; else the linear one.
struct RadiosityQuery {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};
    double brilliance = 1.0;
    double error_bound = 1.0;
    int depth = 0;
    bool smooth = false;
};

// The weighted sum of the records a query may reuse.
struct RadiosityReuse {
    glm::dvec3 weighted{0.0};  // sum of weight x illuminance
    double weight = 0.0;       // sum of weights (POV-Ray's `reuse`)
    void add(const RadiosityRecord& record, const RadiosityQuery& query);
};

class RadiosityCache {
  public:
    // `reach[d]`: the most a query of bounce d multiplies a record's
    // harmonic mean by (its largest error bound): how far a record may be
    // reused, for the index.
    explicit RadiosityCache(std::vector<double> reach) : reach_(std::move(reach)) {}

    void clear();
    // Adds records (after a pass) and indexes them again.
    void add(std::span<const RadiosityRecord> records);
    std::size_t size() const { return records_.size(); }

    // The records of the query's bounce that it may reuse, summed into
    // `into`.
    void gather(const RadiosityQuery& query, RadiosityReuse& into) const;

  private:
    // A bounding volume hierarchy over each record's sphere of reuse, one
    // per bounce, rebuilt after each pass.
    struct Node {
        glm::dvec3 lo{0.0}, hi{0.0};
        std::uint32_t first = 0, count = 0;  // a leaf: its records' range in `order`
        std::uint32_t right = 0;             // count 0: children `first` and `right`
    };
    struct Index {
        std::vector<Node> nodes;
        std::vector<std::uint32_t> order;  // records' indices, leaves' ranges into it
    };
    void build(int depth);
    std::uint32_t build_node(Index& index, std::uint32_t first, std::uint32_t count, int depth);

    std::vector<double> reach_;
    std::vector<RadiosityRecord> records_;
    std::vector<Index> indices_;  // by bounce
};

}  // namespace hexant::tracer
