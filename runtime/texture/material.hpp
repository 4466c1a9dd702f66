// Surface appearance records, after POV-Ray's texture model: a pigment, a
// finish and an interior. Every number may be a function of time.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/boxed_optional.hpp"
#include "runtime/motion/transform.hpp"
#include "runtime/scene/media.hpp"
#include "runtime/shared_value.hpp"
#include "runtime/source_place.hpp"
#include "runtime/sparse_value.hpp"
#include "runtime/texture/pattern/image_map.hpp"
#include "runtime/texture/pattern/pattern.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

// A colour map's entry as the scene wrote it: at `value`, `colour`.
struct ColourMapEntry {
    TimeFunction value;
    ColourFunction colour;
};

// color_map { [v colour] ... } (a value of its own: it may be declared).
struct ColourMap {
    std::vector<ColourMapEntry> entries;  // in order of value
    bool depends_on_time() const;
};

// uv_mapping (POV-Ray's UV_MAP_PATTERN, Parse_Item_Into_Blend_List): a
// pigment, normal or texture read at the surface's (u, v, 0) in place of
// the point (POV-Ray's UVCoord: sphere, box, torus, lathe, sor and mesh
// have their own (u, v); any other shape the world point's x and y),
// through the transforms written in its own block. Nothing from outside
// that block moves it: not the object's transforms, not a texture's, not
// one written around a declared copy (POV-Ray puts those on the outer
// pattern, which a uv map does not warp). Open while its block is being
// written, Closed after.
enum class UvMapping : unsigned char { Off, Open, Closed };

struct Pigment;
// A pigment_map's entry: at `value`, this pigment (evaluated in the space
// of the pattern around it).
struct PigmentMapEntry {
    TimeFunction value;
    std::shared_ptr<const Pigment> pigment;
};

struct Pigment {
    enum class Pattern { Solid, Patterned, Image, Unsupported };
    Pattern pattern = Pattern::Solid;
    // Solid: colours[0].
    std::vector<ColourFunction> colours = std::vector<ColourFunction>(1);
    // Patterned: the pattern (runtime/texture/pattern/pattern.hpp) and its colour
    // map; an empty map is the kind's default. A block pattern's colour
    // list (checker's two) is its map, at values 0, 1, 2.
    SparseValue<pattern::Pattern> patterned;  // (sparse: a plain colour has none)
    ColourMap colour_map;
    // pigment_map { [value pigment] ... }: blends of whole pigments in
    // place of colours (when not empty, the colour map is not used).
    std::vector<PigmentMapEntry> pigment_map;
    // Image: image_map { }, placed by `patterned`'s warps and turbulence
    // (its kind is null: an image has no value of its own) and `transform`.
    std::shared_ptr<const pattern::ImageMap> image_map;
    // The transforms written after the pattern's last warp (all of them,
    // without warps): pattern space to object space.
    Transform transform;
    // For Unsupported: the pattern's name and where it was written, so that
    // using it reports a clear error.
    std::string unsupported_name;
    SourcePlace unsupported_place;
    UvMapping uv_mapping = UvMapping::Off;

    bool depends_on_time() const;
    // Whether some colour it can give, at some time, has a filter or a
    // transmit other than 0 (POV-Ray's HAS_FILTER; an image_map counts,
    // its alpha and filter being per pixel).
    bool may_filter() const;
};

// POV-Ray 3.7's finish and its defaults.
struct Finish {
    // ambient and emission are colours (red, green, blue), as POV-Ray 3.7's
    // (a float is grey).
    std::array<TimeFunction, 3> ambient{0.1, 0.1, 0.1};
    TimeFunction diffuse = 0.6;
    // diffuse's second value (POV-Ray 3.7's DiffuseBack): how much light
    // from behind the surface shows through it (a light, radiosity,
    // photons on the other side), diffusely and without highlights; 0 is none.
    TimeFunction diffuse_back = 0.0;
    TimeFunction brilliance = 1.0;
    TimeFunction phong = 0.0;
    TimeFunction phong_size = 40.0;
    TimeFunction specular = 0.0;
    TimeFunction roughness = 0.05;
    ColourFunction reflection{};  // rgb; zero means none
    std::array<TimeFunction, 3> emission{0.0, 0.0, 0.0};
    // POV-Ray's crand: each light's diffuse intensity less a uniform random
    // fraction of it, per sample (ComputeDiffuseColour); 0 is none.
    TimeFunction crand = 0.0;
    // POV-Ray's metallic: highlights (finish) and the reflection
    // (reflection { metallic }) take on the pigment's colour, by its
    // empirical Fresnel curve (shader.cpp, metallic_tint); 0 is none.
    TimeFunction metallic = 0.0;
    TimeFunction reflection_metallic = 0.0;
    // reflection { MIN, MAX ... }: POV-Ray's variable reflection. `reflection`
    // above is the minimum, seen head-on; the maximum (none: the same) is
    // reached at grazing angles by (1 - cos)^falloff or, with fresnel, by
    // the Fresnel reflectance of the interior's ior (trace.cpp's
    // ComputeReflectivity). The reflected colour is raised to 1 / exponent.
    std::optional<ColourFunction> reflection_max;
    TimeFunction reflection_falloff = 1.0;
    TimeFunction reflection_exponent = 1.0;
    bool reflection_fresnel = false;
    // conserve_energy: what passes through is reduced by what is reflected.
    bool conserve_energy = false;
    // irid { AMOUNT thickness T turbulence V }: thin-film interference on
    // what lights and is reflected (POV-Ray's ComputeIridColour); 0 is none.
    TimeFunction irid = 0.0;
    TimeFunction irid_thickness = 0.0;
    TimeFunction irid_turbulence = 0.0;
    std::vector<Unrendered> unrendered;  // what it asks for that hexant lacks

    // Every scalar time function above (the colours' channels each), with
    // its name for messages, for what walks them all (time dependence,
    // sharing, parameter checks); the reflection colours are apart.
    struct Scalar {
        const TimeFunction* value;
        const char* name;
    };
    std::array<Scalar, 21> scalars() const {
        return {{{&ambient[0], "ambient"},
                 {&ambient[1], "ambient"},
                 {&ambient[2], "ambient"},
                 {&diffuse, "diffuse"},
                 {&diffuse_back, "diffuse's second value"},
                 {&brilliance, "brilliance"},
                 {&phong, "phong"},
                 {&phong_size, "phong_size"},
                 {&specular, "specular"},
                 {&roughness, "roughness"},
                 {&emission[0], "emission"},
                 {&emission[1], "emission"},
                 {&emission[2], "emission"},
                 {&crand, "crand"},
                 {&metallic, "metallic"},
                 {&reflection_metallic, "reflection's metallic"},
                 {&reflection_falloff, "reflection's falloff"},
                 {&reflection_exponent, "reflection's exponent"},
                 {&irid, "irid"},
                 {&irid_thickness, "irid's thickness"},
                 {&irid_turbulence, "irid's turbulence"}}};
    }
};

struct Interior {
    TimeFunction ior = 1.0;
    // Whether `ior` was written: without it POV-Ray takes the
    // atmosphere's index and no dispersion (Parser::Post_Process).
    bool ior_written = false;
    // dispersion D: violet's ior is the written one times sqrt(D), red's
    // divided by it, across `dispersion_samples` bands (tracer/
    // spectral_band.hpp; POV-Ray's Dispersion and Disp_NElems). 1: none.
    TimeFunction dispersion = 1.0;
    int dispersion_samples = 7;
    // fade_distance, fade_power, fade_colour: light that travels d inside
    // the object is dimmed toward fade_colour, by 1 / (1 + (d /
    // fade_distance)^fade_power), or exponentially from a power of 1000 on
    // (POV-Ray 3.7's attenuation, trace.cpp); a distance of 0 is none.
    TimeFunction fade_distance = 0.0;
    TimeFunction fade_power = 0.0;
    ColourFunction fade_colour{};
    // caustics C: POV-Ray's faked caustics, light through the surface
    // brightened by 1 + |cos|^(45 C) at each layer (ComputeShadowTexture);
    // 0 is none.
    TimeFunction caustics = 0.0;
    // media { } inside (runtime/scene/media.hpp), in the order written; in
    // the object's space, moved with it as its texture is.
    std::vector<Media> media;
    void transform_by(const TransformStep& step) {
        for (Media& m : media) m.transform_by(step);
    }
    void transform_by(const Transform& step) {
        for (Media& m : media) m.transform_by(step);
    }
    std::vector<Unrendered> unrendered;  // what it asks for that hexant lacks
};

struct Normal;
// A normal_map's entry: at `value`, this normal (in the space of the
// pattern around it).
struct NormalMapEntry {
    TimeFunction value;
    std::shared_ptr<const Normal> normal;
};
// A slope_map's entry: at `value`, a height and a slope (POV-Ray's
// Point_Slope, through which a pattern's value goes before its slope is
// taken: Hermite cubic between entries).
struct SlopeMapEntry {
    TimeFunction value, height, slope;
};

// normal { PATTERN [AMOUNT] ... }: the shading normal perturbed by a
// pattern (POV-Ray's Perturb_Normal): bumps, dents, ripples, waves,
// wrinkles and quilted by their own functions, any other pattern by its
// slope, sampled `accuracy` apart (through a slope_map when it has one),
// or by a blend of whole normals (normal_map).
struct Normal {
    SparseValue<pattern::Pattern> patterned;  // (sparse: a plain colour has none)
    TimeFunction amount = 0.5;                // bump_size
    TimeFunction accuracy = 0.02;             // POV-Ray's Delta
    bool no_bump_scale = false;
    // normal_map { [value NORMAL_BODY] ... }: the neighbouring entries'
    // normals blended (when not empty, the pattern's own bumps are not used).
    std::vector<NormalMapEntry> normal_map;
    std::vector<SlopeMapEntry> slope_map;  // empty: the pattern's value itself
    // bump_map { }: the normal tilted by an image (pattern/image_map.hpp's
    // bump_map_normal), placed by `patterned`'s warps and turbulence; its
    // kind is then null. bump_size is `amount`.
    std::shared_ptr<const pattern::ImageMap> bump_map;
    // The transforms after the pattern's last warp: pattern space to
    // object space (as Pigment::transform).
    Transform transform;
    // A pattern hexant lacks here (facets, normal_map ...): named, and
    // where it was written, for the error where it is used.
    std::string unsupported_name;
    SourcePlace unsupported_place;
    UvMapping uv_mapping = UvMapping::Off;
    bool depends_on_time() const;
};

struct Texture;
// A texture_map's entry: at `value`, this texture (in the space of the
// pattern around it).
struct TextureMapEntry {
    TimeFunction value;
    std::shared_ptr<const Texture> texture;
};

// POV-Ray's texture, one of two kinds (as its TEXTURE with Type
// PLAIN_PATTERN or a pattern):
// - plain: a pigment, a normal and a finish, and the plain layers under it
//   (texture { A } texture { B }: B on top, A in `below`), each lit and
//   seen through the layers above (POV-Ray's ComputeLightedTexture);
// - patterned (texture_map, or a block pattern's list of textures): the
//   pattern picks whole textures, each lit on its own and the two
//   neighbours' colours blended (POV-Ray's ComputeOneTextureColour).
//   Nothing can be layered over or under it, as in POV-Ray.
struct Texture {
    Pigment pigment;
    BoxedOptional<Normal> normal;  // (boxed: most textures have none)
    // (Shared: equal finishes are one block, FinishPool.)
    SharedValue<Finish> finish;
    // Texture space to object space. For a patterned texture the pattern's
    // own: its transforms after its last warp, then the object's.
    Transform transform;
    // Plain: the layers under this one, bottom first (a layer written on top
    // of a stack of n is added at the end, not in front of n: 10,000 layers
    // read in quadratic time before, issue 45).
    std::vector<Texture> below;
    // Patterned: the pattern and its map (entries at 0, 1, 2 for a block
    // pattern's textures); empty for a plain texture.
    SparseValue<pattern::Pattern> patterned;  // (sparse: a plain colour has none)
    std::vector<TextureMapEntry> texture_map;
    // uv_mapping on the whole texture: its pattern, or its pigment and
    // normal, read at (u, v, 0) through `transform` alone. A Closed one
    // keeps the transforms that come after (the object's) in
    // `uv_outside`: they move none of its points, but a normal still goes
    // through their linear part, into them and back out (POV-Ray's
    // ComputeLightedTexture warps the normal by each enclosing texture's
    // transforms, the uv map's own included).
    UvMapping uv_mapping = UvMapping::Off;
    Transform uv_outside;

    bool is_patterned() const { return !texture_map.empty(); }
    // Whether no light passes it (POV-Ray's OPAQUE_FLAG, Test_Opacity): a
    // plain texture with a layer whose pigment never filters or transmits.
    // A texture_map never is: its entries may differ.
    bool opaque() const;
    // A transformation of the whole texture: this one's and every layer's
    // below (POV-Ray's Transform_Textures). Not into a map's entries: they
    // live in the pattern's space.
    void transform_by(const Transform& step);
    void transform_by(const TransformStep& step);
    bool depends_on_time() const;
};

}  // namespace hexant::runtime
