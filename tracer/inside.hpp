// The interiors a ray is inside (POV-Ray's RayInteriorVector), as far as
// the shader needs them: for its volumes, those with media and the
// non-hollow ones (a ray inside one sees no atmosphere and no fog); for
// refraction, every interior it entered by passing through a surface, in
// the order entered, each with its index of refraction (POV-Ray's
// ComputeRefraction, source/backend/render/trace.cpp, whose rule
// Inside::refract keeps).
#pragma once

#include <algorithm>
#include <array>

#include "runtime/scene/media_volume.hpp"

namespace hexant::tracer {

// N places for a list whose count is kept beside it: the places past the
// count are never read, so they are left uninitialized (every hit makes
// and copies an Inside; its lists are almost always empty).
template <class T, std::size_t N>
struct ListPlaces {
    union {
        std::array<T, N> places;
    };
    ListPlaces() {}
    T& operator[](std::size_t i) { return places[i]; }
    const T& operator[](std::size_t i) const { return places[i]; }
};

// The interiors a ray is inside: at most kMost of each list (deeper
// nesting is not tracked: the innermost beyond it count as outside).
struct Inside {
    static constexpr int kMost = 8;
    struct Entry {
        const void* key = nullptr;  // the media volume, or the object without one
        const runtime::MediaVolume* media = nullptr;
        bool hollow = true;
    };
    ListPlaces<Entry, kMost> entries;
    int count = 0;

    // An interior's indices: its ior, its dispersion (1: none) and the
    // number of bands that splits light into (tracer/spectral_band.hpp).
    struct Index {
        double ior = 1.0;
        double dispersion = 1.0;
        int dispersion_samples = 7;
    };
    // An interior refraction knows: its identity (shared by the members of
    // a CSG and the parts of a mesh, as POV-Ray's Interior is:
    // TextureEvaluator::interior_key) and its indices when the ray entered.
    struct Passed {
        const void* key = nullptr;
        Index index{};
    };
    // What passing a surface does: the ratio of iors and of dispersions
    // (the side the ray comes from over the side it goes to) and the bands
    // a ray of every colour splits into there.
    struct Ratio {
        double ior = 1.0;
        double dispersion = 1.0;
        int dispersion_samples = 7;
    };
    ListPlaces<Passed, kMost> passed;
    int passed_count = 0;

    Inside() {}
    // (Only the places in use are copied.)
    Inside(const Inside& other) { *this = other; }
    Inside& operator=(const Inside& other) {
        count = other.count;
        passed_count = other.passed_count;
        std::copy_n(&other.entries[0], count, &entries[0]);
        std::copy_n(&other.passed[0], passed_count, &passed[0]);
        return *this;
    }

    bool contains(const void* key) const {
        for (int i = 0; i < count; ++i)
            if (entries[std::size_t(i)].key == key) return true;
        return false;
    }
    // POV-Ray's IsHollowRay: every interior around is hollow (an empty
    // list is).
    bool hollow() const {
        for (int i = 0; i < count; ++i)
            if (!entries[std::size_t(i)].hollow) return false;
        return true;
    }
    bool has_media() const {
        for (int i = 0; i < count; ++i)
            if (entries[std::size_t(i)].media) return true;
        return false;
    }
    Inside with(const Entry& e) const {
        Inside out = *this;
        if (!contains(e.key) && out.count < kMost) out.entries[std::size_t(out.count++)] = e;
        return out;
    }
    // (The volumes' lists below keep the refraction list as it is.)
    Inside with_media_only() const {
        Inside out = *this;
        out.count = 0;
        for (int i = 0; i < count; ++i)
            if (entries[std::size_t(i)].media)
                out.entries[std::size_t(out.count++)] = entries[std::size_t(i)];
        return out;
    }
    Inside without(const void* key) const {
        Inside out = *this;
        out.count = 0;
        for (int i = 0; i < count; ++i)
            if (entries[std::size_t(i)].key != key)
                out.entries[std::size_t(out.count++)] = entries[std::size_t(i)];
        return out;
    }

    // Whether interior `key` is on the refraction list (POV-Ray's
    // IsInterior).
    bool holds(const void* key) const {
        for (int i = 0; i < passed_count; ++i)
            if (passed[std::size_t(i)].key == key) return true;
        return false;
    }
    // The list with interior `key` (index `ior`) entered last, unless
    // `once` and it is on it already (a camera ray's start, POV-Ray's
    // AppendInteriors: the members of a union split apart that hold the
    // eye each list the union's interior, so that the ray passes straight
    // through the inner surfaces and bends where it leaves the last).
    Inside entered(const void* key, const Index& index, bool once = true) const {
        Inside out = *this;
        if (once)
            for (int i = 0; i < passed_count; ++i)
                if (passed[std::size_t(i)].key == key) return out;
        if (out.passed_count < kMost) out.passed[std::size_t(out.passed_count++)] = {key, index};
        return out;
    }
    Inside entered(const void* key, double ior, bool once = true) const {
        return entered(key, Index{ior}, once);
    }

    // A ray passing through the surface of interior `key` (indices
    // `index` there): the ratios (the side it comes from over the side it
    // goes to) and, in `next`, the refraction list it goes on with.
    // POV-Ray's rule: an interior it is not in is entered, from the
    // innermost one it is in (nested objects count as outside the ones
    // holding them: (A (B B) A) is (A A|B B|A A)); the innermost one is
    // left into the next; one further out is left with no bending (the
    // overlap of two objects belongs to the one entered last). The
    // atmosphere's index and dispersion are 1. Bands: the interior's own,
    // or leaving into another, the more of the two (POV-Ray's
    // ComputeRefraction). `inside_unknown`: that the ray started inside
    // `key` though its empty list does not say so (a camera ray, whose
    // list POV-Ray fills by inside tests at the eye).
    Ratio refract(const void* key, const Index& index, bool inside_unknown, Inside& next) const {
        next = *this;
        const auto at = [&](int i) -> const Passed& { return passed[std::size_t(i)]; };
        const int bands = index.dispersion_samples;
        if (passed_count > 0 && at(passed_count - 1).key == key) {
            next.passed_count = passed_count - 1;
            if (next.passed_count == 0) return {index.ior, index.dispersion, bands};
            const Index& outer = at(next.passed_count - 1).index;
            return {index.ior / outer.ior, index.dispersion / outer.dispersion,
                    std::max(bands, outer.dispersion_samples)};
        }
        for (int i = 0; i < passed_count - 1; ++i) {
            if (at(i).key != key) continue;
            for (int j = i; j + 1 < passed_count; ++j) next.passed[std::size_t(j)] = at(j + 1);
            next.passed_count = passed_count - 1;
            return {1.0, 1.0, bands};
        }
        if (inside_unknown && passed_count == 0) return {index.ior, index.dispersion, bands};
        const Index from = passed_count > 0 ? at(passed_count - 1).index : Index{};
        if (next.passed_count < kMost) next.passed[std::size_t(next.passed_count++)] = {key, index};
        return {from.ior / index.ior, from.dispersion / index.dispersion, bands};
    }
    double refract(const void* key, double ior, bool inside_unknown, Inside& next) const {
        return refract(key, Index{ior}, inside_unknown, next).ior;
    }
    // The relative index n2 / n1 that Fresnel reflection at the surface of
    // interior `key` (index `ior`) sees: POV-Ray's ComputeRelativeIOR,
    // whose rule differs from refract's: any interior on the list is being
    // left, into the innermost one (itself, when it is the innermost of
    // several: 1), or into the atmosphere when it is the only one.
    double relative_ior(const void* key, double ior, bool inside_unknown) const {
        if (passed_count == 0) return inside_unknown ? 1.0 / ior : ior;
        const double innermost = passed[std::size_t(passed_count - 1)].index.ior;
        for (int i = 0; i < passed_count; ++i)
            if (passed[std::size_t(i)].key == key)
                return passed_count == 1 ? 1.0 / ior : innermost / ior;
        return ior / innermost;
    }
};

}  // namespace hexant::tracer
