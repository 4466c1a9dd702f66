// The Interpreter's objects: the checks of their patterns, the scene's objects and lights, arrays.
// Part of the Interpreter (language/interpreter_state.hpp).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <variant>

#include "language/checked_integer.hpp"
#include "language/interpreter.hpp"
#include "language/interpreter_state.hpp"
#include "language/source_files.hpp"
#include "runtime/objects/parameter_check.hpp"
#include "runtime/texture/evaluation_cost.hpp"

namespace hexant::language {

// ------------------------------------------------------------------ objects

namespace {

// The walks below over an object and the objects nested in it keep their
// own stack, not the thread's: a record may nest kMaxObjectDepth deep, and
// a frame per level overflowed the main thread's 8 MB under AddressSanitizer
// (whose frames are several times larger).

// Calls visit(record) for the object and every object nested in it.
template <class Visit>
void for_each_nested(const runtime::ObjectRecord& object, Visit visit) {
    std::vector<const runtime::ObjectRecord*> pending{&object};
    while (!pending.empty()) {
        const runtime::ObjectRecord* record = pending.back();
        pending.pop_back();
        visit(*record);
        if (const auto* csg = std::get_if<runtime::Csg>(&record->shape))
            for (auto it = csg->children.rbegin(); it != csg->children.rend(); ++it)
                pending.push_back(it->get());  // reversed: children visited in order
    }
}

}  // namespace

// A pattern hexant lacks, in a pigment (its pigment map's too) or a
// normal: the error where the scene uses it (check says it, not only render).
namespace {

// (A declared graph of maps may share entries: each is checked once. A
// texture and its pigment share an address: the kind is part of the key.)
using Checked = std::set<std::pair<int, const void*>>;
void check(const runtime::Pigment& pigment, Checked& seen) {
    if (!seen.insert({0, &pigment}).second) return;
    if (pigment.pattern == runtime::Pigment::Pattern::Unsupported)
        throw ValueError("pigment pattern '" + pigment.unsupported_name + "' (written at " +
                         pigment.unsupported_place.to_string() + ") is not supported by hexant");
    for (const auto& entry : pigment.pigment_map) check(*entry.pigment, seen);
    if (pigment.patterned->pigment) check(*pigment.patterned->pigment, seen);
}
void check(const runtime::Normal& normal, Checked& seen) {
    if (!seen.insert({1, &normal}).second) return;
    if (!normal.unsupported_name.empty())
        throw ValueError("normal pattern '" + normal.unsupported_name + "' (written at " +
                         normal.unsupported_place.to_string() + ") is not supported by hexant");
    for (const auto& entry : normal.normal_map) check(*entry.normal, seen);
    if (normal.patterned->pigment) check(*normal.patterned->pigment, seen);
}
void check(const runtime::Texture& texture, Checked& seen) {
    if (!seen.insert({2, &texture}).second) return;
    check(texture.pigment, seen);
    if (texture.normal) check(*texture.normal, seen);
    for (const auto& layer : texture.below) check(layer, seen);
    for (const auto& entry : texture.texture_map) check(*entry.texture, seen);
    if (texture.patterned->pigment) check(*texture.patterned->pigment, seen);
}

}  // namespace

void check_pigment(const runtime::Pigment& pigment) {
    Checked seen;
    check(pigment, seen);
}
void check_normal(const std::optional<runtime::Normal>& normal) {
    Checked seen;
    if (normal) check(*normal, seen);
}
void check_texture(const runtime::Texture& texture) {
    Checked seen;
    check(texture, seen);
}

namespace {

void check_patterns(const runtime::ObjectRecord& object) {
    for_each_nested(object, [](const runtime::ObjectRecord& record) {
        if (record.texture) check_texture(*record.texture);
        if (record.interior_texture) check_texture(*record.interior_texture);
    });
}

// Each light_group in `record` (under the group `parent`, -1 for none)
// made a group of the scene's, numbered as it is added: the records on the
// way to a group are copied, the others stay shared (a declared group
// placed twice is two groups). Null when nothing in it is a group. Where
// a member of a group has media, `media_in_group` names the first.
runtime::ObjectPtr stamp_light_groups(const runtime::ObjectRecord& record, int parent,
                                      std::vector<runtime::LightGroup>& groups,
                                      std::optional<runtime::SourcePlace>& media_in_group) {
    int here = parent;
    int id = -1;
    if (record.light_group) {
        id = static_cast<int>(groups.size());
        groups.push_back({parent});
        here = id;
    }
    if (here >= 0 && !media_in_group && record.interior && !record.interior->media.empty())
        media_in_group = record.place;
    std::vector<std::pair<std::size_t, runtime::ObjectPtr>> changed;
    if (const auto* csg = std::get_if<runtime::Csg>(&record.shape))
        for (std::size_t i = 0; i < csg->children.size(); ++i)
            if (auto child = stamp_light_groups(*csg->children[i], here, groups, media_in_group))
                changed.emplace_back(i, std::move(child));
    if (id < 0 && changed.empty()) return nullptr;
    auto copy = std::make_shared<runtime::ObjectRecord>(record);
    if (id >= 0) copy->light_group->id = id;
    for (auto& [i, child] : changed) std::get<runtime::Csg>(copy->shape).children[i] = child;
    return copy;
}

// Lights inside CSGs move with them: hand them to the scene with the
// transforms of every object around them. A light_group's own lights
// light its members only (POV-Ray's Promote_Local_Lights: its direct
// children, not lights in unions within it).
void collect_lights(const runtime::ObjectRecord& object,
                    std::vector<runtime::LightRecord>& lights) {
    struct Pending {
        const runtime::ObjectRecord* record;
        // The transform of the objects around it, shared by its siblings: a
        // union of 10^5 objects holds one copy, not one per child.
        std::shared_ptr<const runtime::Transform> outer;
    };
    std::vector<Pending> pending{{&object, std::make_shared<const runtime::Transform>()}};
    while (!pending.empty()) {
        const Pending p = std::move(pending.back());
        pending.pop_back();
        auto here = std::make_shared<runtime::Transform>(p.record->transform);
        here->append(*p.outer);
        for (auto light : p.record->lights) {
            light.transform.append(*here);
            light.light_group = p.record->light_group ? p.record->light_group->id : -1;
            lights.push_back(std::move(light));
        }
        if (const auto* csg = std::get_if<runtime::Csg>(&p.record->shape))
            for (auto it = csg->children.rbegin(); it != csg->children.rend(); ++it)
                pending.push_back({it->get(), here});
    }
}

}  // namespace

void Interpreter::check_parameters(const runtime::ObjectRecord& object,
                                   const p::position& where) const {
    for_each_nested(object, [&](const runtime::ObjectRecord& record) {
        std::optional<std::string> problem = runtime::bad_parameter(record, scene.animation);
        for (std::size_t i = 0; !problem && i < record.lights.size(); ++i)
            problem = runtime::bad_parameter(record.lights[i], scene.animation);
        if (!problem) return;
        if (record.place.file.empty()) fail(where, *problem);
        SceneError error(*problem, place(record.place));
        if (record.place.file != where.source || record.place.line != where.line)
            error.add_context(place(where, "in the object added to the scene here"));
        throw error;
    });
}

namespace {

// Calls visit(note) for what a texture asks for that hexant lacks: its
// finish's, its layers' and its map's entries' (each texture once).
template <class Visit>
void for_each_unrendered(const runtime::Texture& texture, std::set<const void*>& seen,
                         Visit& visit) {
    if (!seen.insert(&texture).second) return;
    for (const auto& note : texture.finish->unrendered) visit(note);
    for (const auto& layer : texture.below) for_each_unrendered(layer, seen, visit);
    for (const auto& entry : texture.texture_map) for_each_unrendered(*entry.texture, seen, visit);
}

}  // namespace

void Interpreter::report_unrendered(const runtime::ObjectRecord& object, const p::position& where) {
    std::set<const void*> seen;
    auto visit = [&](const runtime::Unrendered& note) {
        if (!unrendered_reported_.insert(note.place.to_string() + note.message).second) return;
        const std::string used = where.source + ":" + std::to_string(where.line);
        const std::string at = note.place.to_string();
        if (options.strict) {
            SceneError error(note.message + " (an error under --strict)", place(note.place));
            if (note.place.file != where.source || note.place.line != where.line)
                error.add_context(place(where, "in the object added to the scene here"));
            throw error;
        }
        std::string text = at + ": warning: " + note.message;
        if (note.place.file != where.source || note.place.line != where.line)
            text += " (used by the object at " + used + ")";
        say_warning(std::move(text));
    };
    for_each_nested(object, [&](const runtime::ObjectRecord& record) {
        for (const auto& note : record.unrendered) visit(note);
        if (record.interior)
            for (const auto& note : record.interior->unrendered) visit(note);
        if (record.texture) for_each_unrendered(*record.texture, seen, visit);
        if (record.interior_texture) for_each_unrendered(*record.interior_texture, seen, visit);
        // A kind's own parts' textures (a mesh's faces).
        std::visit(
            [&](const auto& shape) {
                if constexpr (requires { shape.part_textures(); })
                    for (const auto& part : shape.part_textures())
                        for_each_unrendered(part, seen, visit);
            },
            record.shape);
    });
}

namespace {

// Refuses an object whose texture would evaluate past
// runtime::kMostEvaluations at a point (runtime/texture/evaluation_cost.hpp).
void check_evaluation_cost(Interpreter& st, const runtime::ObjectRecord& object,
                           const p::position& where) {
    for_each_nested(object, [&](const runtime::ObjectRecord& record) {
        for (const runtime::Texture* texture :
             {record.texture ? &*record.texture : nullptr, record.interior_texture.get()}) {
            if (texture == nullptr) continue;
            const double cost = runtime::evaluation_cost(*texture);
            if (cost <= runtime::kMostEvaluations) continue;
            std::ostringstream text;
            text << "this object's texture would evaluate up to " << std::setprecision(3) << cost
                 << " pigments, normals and textures at each point (maps whose entries share "
                    "one declared map, nested): more than "
                 << runtime::kMostEvaluations << "; it would not finish";
            st.fail(where, text.str());
        }
    });
}

}  // namespace

void Interpreter::add_object(const runtime::ObjectPtr& given, const p::position& where) {
    runtime::ObjectPtr object = given;
    // Before any walk below: a union doubled 30 times is 2^30 members.
    check_object_count(object->objects, where);
    tell_progress();
    objects_ = runtime::add_objects(objects_, object->objects);
    if (objects_ > options.limits.objects)
        fail(where, "the scene would make more than " + std::to_string(options.limits.objects) +
                        " objects (each member of a CSG, and each copy, is one; --max-objects "
                        "N raises the limit)");
    // An object without a texture takes the #default texture as it is now,
    // not as a later #default leaves it (POV-Ray copies it as it reads the
    // object: Parse_Object_Mods).
    if (!object->texture && defaults_set > 0) {
        auto textured = std::make_shared<runtime::ObjectRecord>(*object);
        textured->texture = scene.default_texture;
        object = std::move(textured);
    }
    try {
        check_patterns(*object);
    } catch (const ValueError& e) {
        fail(where, e);
    }
    check_parameters(*object, where);
    check_evaluation_cost(*this, *object, where);
    report_unrendered(*object, where);
    std::optional<runtime::SourcePlace> media_in_group;
    if (auto stamped = stamp_light_groups(*object, -1, scene.light_groups, media_in_group))
        object = std::move(stamped);
    if (media_in_group)
        warn(where, "the media of the object at " + media_in_group->to_string() +
                        " in a light_group are lit by the scene's lights, not by the group's");
    std::vector<runtime::LightRecord> lights;
    collect_lights(*object, lights);
    scene.objects.push_back(object);
    for (auto& light : lights) add_light(std::move(light), where);
}

void Interpreter::add_light(runtime::LightRecord light, const p::position& where) {
    if (light.looks_like) {
        // POV-Ray's Parse_Light_Source: the object moved to the light's
        // centre and through its own modifiers (as it was read), no_shadow,
        // then transformed with the light. (POV-Ray moves it to the centre
        // as the transforms written before looks_like left it, without
        // turning it by them; hexant turns it by every transform of the
        // light.)
        runtime::ObjectRecord placed = *light.looks_like;
        placed.transform.append(light.transform);
        placed.no_shadow = true;
        placed.lifetime = placed.lifetime.intersect(light.lifetime);
        light.looks_like.reset();
        add_object(std::make_shared<const runtime::ObjectRecord>(std::move(placed)), where);
    }
    if (light.projected_through) {
        // Moved by the light's transforms (POV-Ray's LightSource::Transform
        // moves it; hexant, as with looks_like, by all of them).
        runtime::ObjectRecord placed = *light.projected_through;
        placed.transform.append(light.transform);
        light.projected_through = std::make_shared<const runtime::ObjectRecord>(std::move(placed));
    }
    scene.lights.push_back(std::move(light));
}

void fill_array(Array& array, const Array& list, std::size_t dimension, std::size_t& next) {
    const int want = array.dimensions[dimension];
    if (static_cast<int>(list.elements.size()) != want)
        throw ValueError("the array's dimension " + std::to_string(dimension + 1) + " has " +
                         std::to_string(want) + " elements but " +
                         std::to_string(list.elements.size()) + " were given");
    for (const auto& element : list.elements) {
        const Value& v = **element;
        const bool is_list =
            v.is<std::shared_ptr<Array>>() && v.as<std::shared_ptr<Array>>()->dimensions.empty();
        if (dimension + 1 < array.dimensions.size()) {
            if (!is_list) throw ValueError("expected a { } list for the array's next dimension");
            fill_array(array, *v.as<std::shared_ptr<Array>>(), dimension + 1, next);
        } else {
            if (is_list) throw ValueError("the array has fewer dimensions than this { } list");
            array.charge.add(element_bytes(v));
            array.elements[next++] = std::make_shared<Value>(v);
        }
    }
}

namespace {

// A shape block's values for its kind's read (runtime/objects/shape_arguments.hpp),
// converted by the language's own rules; errors are ValueErrors, which the
// rule reading the block places.
class BlockArguments final : public runtime::objects::ShapeArguments {
  public:
    BlockArguments(std::string keyword, std::vector<std::string> options,
                   std::vector<Value>& values, const Interpreter& st, const p::position& where)
        : keyword_(std::move(keyword)),
          options_(std::move(options)),
          values_(values),
          st_(st),
          where_(where) {}

    const std::string& keyword() const override { return keyword_; }
    const std::vector<std::string>& options() const override { return options_; }
    std::size_t size() const override { return values_.size(); }
    TimeFunction number(std::size_t i, const std::string& what) const override {
        return to_float(at(i), what);
    }
    runtime::Vector3Function vector3(std::size_t i, const std::string& what) const override {
        return to_vector3(at(i), what);
    }
    runtime::Vector2Function vector2(std::size_t i, const std::string& what) const override {
        return to_vector2(at(i), what);
    }
    double constant(std::size_t i, const std::string& what) const override {
        return to_constant(at(i), what);
    }
    std::string string(std::size_t i, const std::string& what) const override {
        return to_string_value(at(i), what);
    }
    std::filesystem::path find_file(const std::string& name,
                                    const std::string& kind) const override {
        if (name.empty()) fail(keyword_ + "'s " + kind + " name is empty");
        // Also where POV-Ray's default library path finds them on Debian;
        // the system's fonts may be named by their path.
        return st_.resolve_include(name, where_, kind,
                                   {kPovRayIncludeDir, kPovRayFontDir, "/usr/share/fonts"});
    }
    const std::string& charset() const override { return st_.charset; }
    std::size_t max_image_pixels() const override { return st_.max_image_pixels(); }
    [[noreturn]] void fail(const std::string& message) const override { throw ValueError(message); }

  private:
    const Value& at(std::size_t i) const {
        if (i >= values_.size()) fail(keyword_ + " has no value " + std::to_string(i + 1));
        return values_[i];
    }

    std::string keyword_;
    std::vector<std::string> options_;
    std::vector<Value>& values_;
    const Interpreter& st_;
    p::position where_;
};

// Reads the kind at `index` of the list (kinds with a rule of their own
// are never read here).
template <class... Kinds>
void read_shape(std::size_t index, const runtime::objects::ShapeArguments& args,
                runtime::ObjectRecord& record, runtime::objects::KindList<Kinds...>) {
    std::size_t i = 0;
    const bool found =
        ((i++ == index
              ? (
                    [&] {
                        if constexpr (!runtime::objects::kind_detail::own_syntax<Kinds>()) {
                            record.shape = Kinds::read(args);
                            // What POV-Ray applies before the scene's
                            // own transformations.
                            if constexpr (requires { Kinds::placement(); })
                                record.transform = Kinds::placement();
                        }
                    }(),
                    true)
              : false) ||
         ...);
    if (!found) throw std::logic_error("hexant: no shape kind " + std::to_string(index));
}

// The most objects one shape may become by strings that change with clock
// (str(clock) over 10,000 frames is 10,000 texts).
constexpr std::size_t kMaxTimedStringObjects = 100'000;

}  // namespace

runtime::ObjectRecord make_shape(const Interpreter::ShapeOpening& shape, std::vector<Value>& args,
                                 Interpreter& st, const p::position& where) {
    const std::string kind(runtime::objects::kind_keyword(runtime::ShapeKinds{}, shape.kind));
    // A string value that changes with clock (str(clock, 0, 2), a branch on
    // clock naming two fonts): one object per text, each living while its
    // text holds, together in a union. (Further such strings split each.)
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (!args[i].is<TimedString>()) continue;
        const auto texts = args[i].as<TimedString>().by_text();
        if (texts.size() > kMaxTimedStringObjects)
            throw ValueError(kind + "'s value " + std::to_string(i + 1) +
                             " changes with clock into " + std::to_string(texts.size()) +
                             " different strings, more than " +
                             std::to_string(kMaxTimedStringObjects) + " objects");
        runtime::Csg group;
        for (const auto& [text, life] : texts) {
            std::vector<Value> one = args;
            one[i] = Value{text};
            runtime::ObjectRecord child = make_shape(shape, one, st, where);
            child.lifetime = child.lifetime.intersect(life);
            child.place = shape.place;
            group.children.push_back(
                std::make_shared<const runtime::ObjectRecord>(std::move(child)));
        }
        runtime::ObjectRecord record;
        record.shape = std::move(group);
        return record;
    }
    // A text makes a glyph a character, each about an object's memory
    // (3.6 KB): counted against Limits::objects before they are laid out
    // (a text of 16 Mi characters took 12 GB in 60 s, issue 45). Its
    // string's code points (the string after the font's name).
    std::uint64_t characters = 1;
    if (kind == runtime::Text::keyword)
        for (std::size_t i = 1; i < args.size(); ++i)
            if (const Value& arg = args[i]; arg.is<std::string>()) {
                const std::string& text = arg.as<std::string>();
                const auto code_points =
                    static_cast<std::uint64_t>(std::count_if(text.begin(), text.end(), [](char c) {
                        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
                    }));
                characters = std::max(characters, code_points);
            }
    if (characters > st.options.limits.objects)
        st.fail(where, "this text has " + std::to_string(characters) +
                           " characters, each glyph an object: more than the limit of " +
                           std::to_string(st.options.limits.objects) +
                           " objects (--max-objects N raises it)");
    const BlockArguments arguments(kind, shape.options, args, st, where);
    runtime::ObjectRecord record;
    read_shape(shape.kind, arguments, record, runtime::ShapeKinds{});
    record.objects = record.own_objects();
    return record;
}

void set_shape_setting(runtime::ObjectRecord& record, const std::string& name,
                       std::vector<Value>& values, Interpreter& st, const p::position& where) {
    const BlockArguments value(name, {}, values, st, where);
    bool taken = false;
    std::visit(
        [&](auto& shape) {
            using Kind = std::decay_t<decltype(shape)>;
            if constexpr (requires { shape.set(name, value); })
                if (runtime::objects::takes_setting<Kind>(name)) {
                    shape.set(name, value);
                    taken = true;
                }
        },
        record.shape);
    if (taken) return;
    // Which kinds it belongs to, for the message.
    std::vector<std::string> owners;
    [&]<class... Kinds>(runtime::objects::KindList<Kinds...>) {
        ((runtime::objects::takes_setting<Kinds>(name) ? (owners.emplace_back(Kinds::keyword), 0)
                                                       : 0),
         ...);
    }(runtime::ShapeKinds{});
    std::string kinds;
    for (std::size_t i = 0; i < owners.size(); ++i)
        kinds += (i == 0 ? "" : i + 1 == owners.size() ? " or " : ", ") + owners[i];
    throw ValueError("'" + name + "' belongs to a " + kinds + ", not a " +
                     runtime::shape_name(record.shape));
}

void add_blob_component(runtime::ObjectRecord& record, const std::string& kind,
                        std::vector<Value>& values, Interpreter& st, const p::position& where) {
    auto* blob = std::get_if<runtime::Blob>(&record.shape);
    if (!blob) throw ValueError("a blob component belongs in a blob");
    const BlockArguments args("blob " + kind, {}, values, st, where);
    blob->add_component(kind, args);
}

void set_blob_component_modifiers(runtime::ObjectRecord& record, runtime::ObjectRecord own,
                                  const p::position&) {
    auto* blob = std::get_if<runtime::Blob>(&record.shape);
    if (!blob) throw ValueError("a blob component belongs in a blob");
    if (own.transform.has_deformation())
        throw ValueError(
            "a blob component cannot be twisted, tapered or bent (POV-Ray's components take "
            "translate, rotate, scale and matrix); deform the whole blob instead");
    blob->set_component_modifiers(std::move(own.transform), std::move(own.texture));
}

}  // namespace hexant::language
