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
// from kNumbers at a random place, or a random span wrapped in one opener
// repeated up to thousands of times.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
    std::minstd_rand random(seed);
    if (random() % 4 != 0 || size == 0) return LLVMFuzzerMutate(data, size, max_size);
    std::string text(reinterpret_cast<const char*>(data), size);
    const std::size_t at = random() % (text.size() + 1);
    if (random() % 2 == 0) {
        text.insert(at, kNumbers[random() % std::size(kNumbers)]);
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
