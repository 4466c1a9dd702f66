// libFuzzer over hexant's reading of a scene and the render of a tiny frame
// (README, "Fuzzing"). Any scene must end in an image or a SceneError (or
// another reported error): a crash, a sanitizer report, a leak or a hang
// is a bug. Built only with clang (-DHEXANT_FUZZ=ON; `make fuzz`).
//
// The limits are lowered so that one input takes milliseconds, not the
// minutes a scene may take within the defaults: the fuzzer looks for
// crashes, and a limit met is a clean error.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <random>
#include <sstream>
#include <string>

#include "language/interpreter.hpp"
#include "runtime/geometry/curved_path_root.hpp"
#include "tracer/renderer.hpp"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

hexant::language::ParseOptions fuzz_options(std::ostream& messages) {
    hexant::language::ParseOptions options;
    options.messages = &messages;
    options.animation.width = 8;
    options.animation.height = 8;
    options.animation.final_frame = 3;  // clock runs: time functions are checked and rendered
    auto& limits = options.limits;
    // A loop's cost is its iterations times its body's length, re-read at
    // each turn: an 18 KB body turning 2,000 times took 0.7 s in the release
    // build and over 20 s (libFuzzer's timeout, a false hang) under the
    // sanitizers. So fewer turns here; real scenes keep the defaults.
    limits.loop_iterations = 250;
    limits.total_iterations = 2'500;
    // And less text: a loop stepping over a 50 KB body 250 times took over
    // 20 s under the sanitizers (tests/scenes/fuzz_found/switch_skip_hang.pov).
    limits.text_read = 1 << 20;
    limits.string_length = 1 << 16;
    limits.array_memory = 16u << 20;
    // A condition on clock that stays undecided spends the splitting's
    // whole budget (256 evaluations a piece): 2.6 s in the release build at
    // 10^4 pieces, over 10 s under the sanitizers (a slow unit on the seed
    // tests/fuzz/corpus/time_branches.pov, mutated).
    limits.time_pieces = 1000;
    // Images a scene names (POV-Ray's own: plasma2.png, Mount1.png,
    // mtmand.pot) are found where Debian's povray-includes puts them, and
    // held to fewer pixels (the largest there has 64,000).
    options.include_paths = {"/usr/share/povray-3.7/include"};
    limits.image_pixels = 1 << 20;
    return options;
}

// Pieces the structure-aware mutator splices in: deep nesting (which the
// byte mutations almost never build) and the numbers that break
// arithmetic.
const char* const kNumbers[] = {"sqrt(-1)",
                                "1e308*10",
                                "-1e308*10",
                                "1/0",
                                "0/0",
                                "1e-320",
                                "2147483648",
                                "-2147483649",
                                "9007199254740993",
                                "1e300",
                                "(clock-0.5)",
                                "1/(clock-0.5)",
                                "sqrt(0.5-clock)",
                                "nan",
                                "inf"};
// Whole items a scene brings from outside or builds deep, whose syntax the
// byte mutations rarely hit: images and fonts found where POV-Ray's
// includes are (Debian's povray-includes and fonts-povray), maps, layers
// and meshes. (libFuzzer's dictionary keeps words of at most 64 bytes.)
const char* const kItems[] = {
    "sphere{0,1 pigment{image_map{png \"plasma2.png\" interpolate 2 once}}}",
    "sphere{0,1 pigment{image_map{gif \"mtmand.pot\" map_type 1 filter all 0.5}}}",
    "plane{y,0 normal{bump_map{png \"bumpmap_.png\" use_index bump_size 3}}}",
    "box{0,1 texture{material_map{png \"test.png\" texture{pigment{rgb 1}} "
    "texture{pigment{rgb x}}}}}",
    "height_field{png \"Mount1.png\" smooth water_level 0.2 scale <2,0.5,2>}",
    "height_field{pot \"mtmand.pot\"}",
    "height_field{function 9,9{pigment{bozo color_map{[0 rgb 0][1 rgb 1]}}}}",
    "text{ttf \"timrom.ttf\" \"AVAWTo\",0.3,<0.1,0.2,0> pigment{rgb 1}}",
    "text{ttf \"crystal.ttf\" concat(\"x\",str(clock,0,2)),clock,0}",
    "text{internal 0 \"\xc3\xa9t\xc3\xa9\",-0.1,0}",
    "pigment{gradient x pigment_map{[0 checker rgb 1 rgb 0][0.5 rgb y][1 bozo]}}",
    "normal{bozo normal_map{[0 bumps 0.5][1 dents 2 scale 0.1]} slope_map{[0 <0,1>][1 <1,0>]}}",
    "texture{checker texture{pigment{rgb 1}} texture{gradient y texture_map{[0 pigment{rgb 0}]"
    "[1 pigment{rgb 1}]}}}",
    "texture{pigment{rgb 1}}texture{pigment{bozo color_map{[0 rgbt 1][1 rgbf 0.5]}}"
    "finish{phong 1}}",
    "mesh2{vertex_vectors{4,0,x,y,z} uv_vectors{2,0,1} texture_list{2,texture{pigment{rgb 1}}"
    "texture{pigment{rgb 0}}} face_indices{2,<0,1,2>,0,<1,2,3>,1} uv_indices{2,<0,1,1>,"
    "<1,0,0>} inside_vector y}",
    "mesh{triangle{0,x,y} smooth_triangle{0,z,x,z,y,z} triangle{0,1,1}}",
    "isosurface{function{x*x+y*y+z*z-clock} contained_by{sphere{0,2}} threshold 0.1 open}",
    "sphere_sweep{b_spline 4,0,0.5,x,0.2,y,0.3,z,0.1}",
    "blob{threshold 0.6 sphere{0,1,1} cylinder{0,x*clock,0.5,-2}}",
    "lathe{bezier_spline 4,<0,0>,<1,0>,<1,1>,<0,1>}",
    "prism{0,1,4,<0,0>,<1,0>,<0,1>,<0,0>}",
    "superellipsoid{<0.1,3>}",
    "julia_fractal{<-0.1,0.6,0,0> quaternion sqr max_iteration 8 precision 10}",
    "bicubic_patch{type 1 u_steps 3 v_steps 3 <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>,<0,1,0>,<1,1,1>,"
    "<2,1,1>,<3,1,0>,<0,2,0>,<1,2,1>,<2,2,1>,<3,2,0>,<0,3,0>,<1,3,0>,<2,3,0>,<3,3,0>}",
    "poly{4,<1,0,0,0,1,0,0,0,0,-0.5,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1>}",
};
const char* const kOpeners[][2] = {{"(", ")"},      {"<", ",0,0>"},     {"-", ""},
                                   {"union{", "}"}, {"#if(1)", "#end"}, {"/*", "*/"},
                                   {"{", "}"},      {"sin(", ")"},      {"array[1]{", "}"}};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    // A deformed object's curved-path search gives up after 1,024 pieces,
    // not 65,536: a twist of 8e18 degrees a unit with a taper of 5e8 meets
    // the limit in every search (2 s for an 8 by 8 frame in the release
    // build, a timeout under the sanitizers); the fuzzer looks for crashes.
    hexant::runtime::g_curved_path_max_pieces.store(1024, std::memory_order_relaxed);
    std::ostringstream messages;
    const auto options = fuzz_options(messages);
    try {
        const auto scene = hexant::language::parse_scene_text(text, "fuzz.pov", options);
        hexant::tracer::RenderSettings settings;
        settings.threads = 1;
        settings.first_frame = 1;
        settings.last_frame = 1;
        hexant::tracer::Renderer renderer(scene, settings);
        (void)renderer.render_frame(1);
    } catch (const std::exception&) {
        // A reported error: what the fuzzer wants to see.
    }
    return 0;
}

// Mostly libFuzzer's own mutations; one in four splices a piece: a number
// from kNumbers or an item from kItems at a random place, or a random span
// wrapped in one opener repeated up to thousands of times.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
    std::minstd_rand random(seed);
    if (random() % 4 != 0 || size == 0) return LLVMFuzzerMutate(data, size, max_size);
    std::string text(reinterpret_cast<const char*>(data), size);
    const std::size_t at = random() % (text.size() + 1);
    const auto choice = random() % 3;
    if (choice == 0) {
        text.insert(at, kNumbers[random() % std::size(kNumbers)]);
    } else if (choice == 1) {
        text.insert(at, kItems[random() % std::size(kItems)]);
    } else {
        const auto& pair = kOpeners[random() % std::size(kOpeners)];
        const std::size_t end = at + random() % (text.size() - at + 1);
        const std::size_t depth = std::size_t(1) << (random() % 15);  // 1 .. 16384
        std::string open, close;
        for (std::size_t i = 0; i < depth && open.size() + close.size() < max_size; ++i) {
            open += pair[0];
            close += pair[1];
        }
        text = text.substr(0, at) + open + text.substr(at, end - at) + close + text.substr(end);
    }
    if (text.size() > max_size) text.resize(max_size);
    std::memcpy(data, text.data(), text.size());
    return text.size();
}
