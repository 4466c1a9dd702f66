// What a shape's block held, as each object kind reads it (pbrt-v4's
// ParameterDictionary, as a shape's Create reads it): the words before its
// values (prism's `linear_sweep`, text's `ttf`), its values in order, and,
// for a setting after them (`open`, `tolerance 1e-6`), that setting's
// value. The language supplies it; a kind's `read` takes what it needs
// through the typed getters, each of which names what it wanted in the
// error it throws (`what` is a phrase such as "the sphere's radius").
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "runtime/time/vector_function.hpp"

namespace hexant::runtime::objects {

class ShapeArguments {
  public:
    virtual ~ShapeArguments() = default;

    // The kind's keyword, for messages ("sphere").
    virtual const std::string& keyword() const = 0;
    // The words before the values, in order.
    virtual const std::vector<std::string>& options() const = 0;
    virtual std::size_t size() const = 0;

    // Value i as POV-Ray converts it where the kind wants this type: a
    // float may be a time function; a float given for a vector is promoted
    // to all components; a 2-vector given for a 3-vector gets z = 0. Throw
    // (the language's error, placed where the block was written) when value
    // i has another type.
    virtual TimeFunction number(std::size_t i, const std::string& what) const = 0;
    virtual Vector3Function vector3(std::size_t i, const std::string& what) const = 0;
    virtual Vector2Function vector2(std::size_t i, const std::string& what) const = 0;
    // A number that must be known while the scene is read (a count).
    virtual double constant(std::size_t i, const std::string& what) const = 0;
    virtual std::string string(std::size_t i, const std::string& what) const = 0;
    // A file named `name`, found as an #include is (the scene's folder, the
    // library path, then POV-Ray's own folders), confined as includes are;
    // `kind` for messages ("font file").
    virtual std::filesystem::path find_file(const std::string& name,
                                            const std::string& kind) const = 0;
    // global_settings { charset ascii | utf8 }: how a string's bytes become
    // characters ("ascii", POV-Ray's default, or "utf8").
    virtual const std::string& charset() const = 0;
    // The pixels an image the block reads may declare (the scene's
    // --max-pixels, Limits::image_pixels).
    virtual std::size_t max_image_pixels() const = 0;

    // Throws the language's error with this message.
    [[noreturn]] virtual void fail(const std::string& message) const = 0;

    // The file named by string i (find_file).
    std::filesystem::path file(std::size_t i, const std::string& kind) const {
        return find_file(string(i, keyword() + "'s " + kind + " name"), kind);
    }
    // A count in [lo, hi] (truncated toward zero, as POV-Ray's casts).
    long long count(std::size_t i, const std::string& what, long long lo, long long hi) const;
    // Fails unless lo <= size() <= hi: "<keyword> needs <what>, but N values were given".
    void need(std::size_t lo, std::size_t hi, const std::string& what) const;
    // Fails on any option word (for kinds that take none).
    void no_options() const;
};

}  // namespace hexant::runtime::objects
