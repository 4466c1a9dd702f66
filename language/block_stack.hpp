// The blocks under construction while a scene is read (the Interpreter's
// block stack): `sphere { ... }`, `texture { ... }`, the innermost on top.
// An action opens a block at its `{`, edits the top one as its items are
// read and closes it at its `}`.
//
// A side of a time split (Interpreter::split_time) may add CSG members to
// the object block around it and change its texture (made piecewise in
// time), but not edit it otherwise: the stack counts the edits of a
// watched block, and those that are not of its texture, to tell.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <tao/pegtl.hpp>

#include "language/image_map_file.hpp"
#include "language/value.hpp"
#include "runtime/scene/scene.hpp"

namespace hexant::language {

struct SplineBuilder {
    runtime::SplineKind kind = runtime::SplineKind::Linear;
    std::vector<runtime::Spline::Key> keys;
    int dimensions = 1;
};

using MaterialBuilder = Material;

// image_map { } being read: the map, the file as read (decoded when the
// block closes, after its gamma), and what was said of it.
struct ImageMapBuilder {
    runtime::pattern::ImageMap map;
    // The files as read, over their pieces of time (one piece for a file
    // named once), and each distinct file once.
    std::vector<std::pair<runtime::Interval, std::shared_ptr<const image::StoredImage>>> stored;
    ImageGamma gamma;
    bool gamma_srgb_next = false;  // `gamma srgb` just read
    bool all_next = false;         // `filter all` / `transmit all` being read
    bool bump = false;             // a normal's bump_map { }
    std::string type_word;         // the file's type as written (tga), or empty
    // A material_map's textures, in the order written.
    std::vector<std::shared_ptr<const runtime::Texture>> materials;
    std::optional<TimeFunction> bump_size;
};

// A block under construction.
using Block = std::variant<runtime::ObjectRecord, runtime::LightRecord, runtime::CameraRecord,
                           runtime::Texture, runtime::Pigment, runtime::Normal, runtime::ColourMap,
                           runtime::SkySphere, runtime::Fog, runtime::Finish, runtime::Interior,
                           runtime::Media, runtime::Transform, SplineBuilder, MaterialBuilder,
                           ImageMapBuilder, runtime::Rainbow>;

class BlockStack {
  public:
    template <typename... Args>
    void open(Args&&... args) {
        blocks_.emplace_back(std::forward<Args>(args)...);
    }
    Block& top() { return blocks_.back(); }
    const Block& top() const { return blocks_.back(); }
    // Takes the top block off.
    void close() { blocks_.pop_back(); }
    std::size_t depth() const { return blocks_.size(); }
    bool empty() const { return blocks_.empty(); }
    // The block the top one is inside; null when there is none.
    const Block* around_top() const {
        return blocks_.size() < 2 ? nullptr : &blocks_[blocks_.size() - 2];
    }
    // Closes every block above `depth` (a reading abandoned inside them).
    void rewind(std::size_t depth) {
        if (blocks_.size() > depth)
            blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(depth), blocks_.end());
    }

    // The top block as a T, to be edited; throws a parse error at `where`
    // ("`what` does not belong here") when the top is not a T.
    template <typename T>
    T& edit(const tao::pegtl::position& where, const char* what) {
        if (blocks_.size() == watched_) {
            ++edits_;
            // (An object's texture, pigment, normal or finish: "a texture".)
            if (std::string_view(what) != "a texture") ++other_edits_;
        }
        return top_as<T>(where, what);
    }
    // The object block a CSG member or light joins: edit() without counting
    // an edit (members added under a time split live on its pieces).
    runtime::ObjectRecord& join(const tao::pegtl::position& where) {
        return top_as<runtime::ObjectRecord>(where, "an object");
    }

    // Watching the block at `depth` (0: none) for edits, from now on; gives
    // what was watched before, for end_watch or abandon_watch.
    struct Watch {
        std::size_t depth = 0, edits = 0, other_edits = 0;
    };
    Watch watch(std::size_t depth) {
        const Watch before{watched_, edits_, other_edits_};
        watched_ = depth;
        edits_ = 0;
        other_edits_ = 0;
        return before;
    }
    // How the watched block was edited since watch().
    enum class Edited { No, TextureOnly, Otherwise };
    // The watched block's edits since watch(); the watch before it
    // resumes, counting these as one edit of the same kind.
    Edited end_watch(const Watch& before) {
        const Edited edited = edits_ == 0         ? Edited::No
                              : other_edits_ == 0 ? Edited::TextureOnly
                                                  : Edited::Otherwise;
        watched_ = before.depth;
        edits_ = before.edits + (edits_ > 0 ? 1 : 0);
        other_edits_ = before.other_edits + (other_edits_ > 0 ? 1 : 0);
        return edited;
    }
    // The watch before resumes as it was (a side abandoned by an error).
    void abandon_watch(const Watch& before) {
        watched_ = before.depth;
        edits_ = before.edits;
        other_edits_ = before.other_edits;
    }

  private:
    template <typename T>
    T& top_as(const tao::pegtl::position& where, const char* what) {
        if (blocks_.empty() || !std::holds_alternative<T>(blocks_.back()))
            throw tao::pegtl::parse_error(std::string(what) + " does not belong here", where);
        return std::get<T>(blocks_.back());
    }

    std::vector<Block> blocks_;
    std::size_t watched_ = 0, edits_ = 0, other_edits_ = 0;
};

}  // namespace hexant::language
