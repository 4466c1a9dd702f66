// hexant against POV-Ray 3.7 on photon mapping (global_settings { photons
// { } }): caustics through a glass ball and off a mirror, a spotlight whose
// photons do not refract, an object that collects none (the scene and the
// commands that made POV-Ray's images: pov_reference/README.md).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "pov_reference_compare.hpp"

using namespace hexant::test::pov_reference;

namespace {

const fs::path kScene = kFolder / "photons" / "photons.pov";

// The light photons add: per channel, the linear light of `lit` above that
// of `dark` (the same scene without photons), summed over the image.
double added_light(const Pixels& lit, const Pixels& dark) {
    double sum = 0.0;
    for (std::size_t i = 0; i < lit.rgb.size(); ++i)
        sum += std::max(0.0, linear_light(lit.rgb[i]) - linear_light(dark.rgb[i]));
    return sum;
}

// How many pixels photons light by more than 0.05 (linear, summed over
// the channels).
int lit_pixels(const Pixels& lit, const Pixels& dark) {
    int n = 0;
    for (std::size_t i = 0; i + 2 < lit.rgb.size(); i += 3) {
        double a = 0.0;
        for (int c = 0; c < 3; ++c)
            a += std::max(0.0, linear_light(lit.rgb[i + c]) - linear_light(dark.rgb[i + c]));
        n += a > 0.05;
    }
    return n;
}

// A still of photons/`name`.pov at 128x96, one ray a pixel (plus
// `flags`): its image and what --stats counted in the row `counter`.
std::pair<Pixels, double> still_counting(const std::string& name, const std::string& flags,
                                         const std::string& counter) {
    const fs::path out = fs::temp_directory_path() / ("hexant_photons_" + name + ".png");
    fs::remove(out);
    const Ran ran = run_command(
        std::string(HEXANT_BINARY) + " render " + (kFolder / "photons" / (name + ".pov")).string() +
        " -W 128 -H 96 --spp 1 --no-jitter --shutter 0 --stats " + flags + " -o " + out.string());
    REQUIRE(ran.ok);
    const std::size_t at = ran.said.find(counter);
    REQUIRE(at != std::string::npos);
    return {read_png(out), std::stod(ran.said.substr(at + counter.size()))};
}

Pixels hexant_still(const std::string& flags, const std::string& name) {
    return render(kScene, flags, name, 0, "-W 128 -H 96");
}

}  // namespace

TEST_CASE("photons make POV-Ray 3.7's caustics", "[tracer][pov][photons]") {
    // Both renderers shoot the same grid of photons (spacing 0.01 at the
    // targets), jittered by their own random numbers, and estimate from the
    // nearest 100: the caustics' edges differ by their noise. When written:
    // 98.1% of the pixels within 2 steps, mean 0.21, worst 32 at clock 0;
    // 97.2%, 0.25, 30 at clock 1 (the ball moved). Without photons: 91.5%
    // within 2 steps, mean 6.78, worst 163 (the caustics are a small part
    // of the image: their light is checked below too). Stored photons when
    // written: POV-Ray 36,225, hexant 36,232.
    for (const char* clock : {"0", "1"}) {
        INFO("clock " << clock);
        const Agreement a =
            agree(hexant_still("--clock " + std::string(clock), "hexant_pov_photons"),
                  read_png(kFolder / "photons" / ("photons_" + std::string(clock) + ".png")));
        INFO("within " << a.within << " of " << a.total << ", mean " << a.mean << ", worst "
                       << a.worst);
        CHECK(a.within >= a.total * 96 / 100);
        CHECK(a.mean < 0.45);
    }
}

TEST_CASE("photons add as much light as POV-Ray's", "[tracer][pov][photons]") {
    // The caustics' light over the image, above the scene without photons
    // (POV-Ray's own image of it): POV-Ray 250.8, hexant 254.7 (+1.6%)
    // when written. A photon's power taken from the wrong distance (the
    // first hit's, not the path's) or the Lambertian compensation left out
    // moves it by tens of percent; reflections followed without POV-Ray's
    // squared weight stored twice the photons.
    const Pixels dark = read_png(kFolder / "photons" / "photons_none_0.png");
    const double pov = added_light(read_png(kFolder / "photons" / "photons_0.png"), dark);
    const double ours = added_light(hexant_still("--clock 0", "hexant_pov_photons_light"), dark);
    INFO("POV-Ray " << pov << ", hexant " << ours);
    CHECK(pov > 200.0);
    CHECK(ours == Approx(pov).epsilon(0.06));
    // Without photons hexant's image is POV-Ray's own.
    const double none =
        added_light(hexant_still("--clock 0 --declare Photons=0", "hexant_pov_photons_none"), dark);
    CHECK(none < 1.0);
}

TEST_CASE("a frame's photons are the same whatever the threads", "[tracer][photons]") {
    // Each ring of photons is shot into its own list and the lists joined
    // in order; each photon's random numbers are a hash of its place.
    const auto one = render(kScene, "--clock 0.5 --threads 1", "hexant_photon_threads", 0,
                            "-W 48 -H 36", "--spp 2");
    const auto two = render(kScene, "--clock 0.5 --threads 2", "hexant_photon_threads", 0,
                            "-W 48 -H 36", "--spp 2");
    CHECK(one.rgb == two.rgb);
}

TEST_CASE("a moving glass's caustic blurs across the shutter", "[tracer][photons]") {
    // Frame 1 of 2 over clock 0 to 1: the ball rolls 0.6 while the shutter
    // is open (--shutter 1). Photons shot at their own times across it
    // spread the caustic along the ball's way: at 64x48, 4 samples, when
    // written 178 pixels lit by photons against 131 with the shutter
    // closed (the ball at clock 0). Photons shot at one instant (the
    // frame's middle) lit 130 with the shutter open.
    const auto frame = [&](const std::string& flags, const std::string& name) {
        const fs::path out = fs::temp_directory_path() / (name + "_0001.png");
        fs::remove(out);
        const std::string command =
            std::string(HEXANT_BINARY) + " render " + kScene.string() +
            " +KFI0 +KFF2 +KI0 +KF1 --frames 1 -W 64 -H 48 --spp 4 " + flags + " -o " +
            (fs::temp_directory_path() / (name + "_####.png")).string() + " > /dev/null";
        REQUIRE(std::system(command.c_str()) == 0);
        return read_png(out);
    };
    const int still = lit_pixels(frame("--shutter 0", "hexant_photon_blur_still"),
                                 frame("--shutter 0 --declare Photons=0", "hexant_photon_blur_sd"));
    const int open = lit_pixels(frame("--shutter 1", "hexant_photon_blur_open"),
                                frame("--shutter 1 --declare Photons=0", "hexant_photon_blur_od"));
    INFO("lit pixels: shutter closed " << still << ", open " << open);
    CHECK(still > 60);
    CHECK(open > still * 5 / 4);
}

TEST_CASE("a spacing that would shoot too many photons is refused", "[tracer][photons]") {
    // 10^-6 at a ball of radius 1: about 3 x 10^12 photons, which would
    // take the machine's memory; refused before any is shot, naming the
    // setting, with a non-zero exit and no image.
    const fs::path scene = fs::temp_directory_path() / "hexant_photon_limit.pov";
    const fs::path out = fs::temp_directory_path() / "hexant_photon_limit.png";
    {
        std::ofstream text(scene);
        text << "global_settings { photons { spacing 0.000001 } }\n"
                "camera { location -5 * z look_at 0 }\n"
                "light_source { <0, 5, -5> rgb 1 }\n"
                "sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 }\n"
                "  photons { target refraction on } }\n";
    }
    fs::remove(out);
    const std::string command =
        std::string(HEXANT_BINARY) + " render " + scene.string() + " -W 8 -H 6 -o " + out.string();
    const Ran ran = run_command(command);
    CHECK_FALSE(ran.ok);
    const std::string& said = ran.said;
    INFO(said);
    CHECK(said.find("photons: the spacing") != std::string::npos);
    CHECK(said.find("raise photons' spacing") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("a photon splits into the bands of a dispersive target",
          "[tracer][photons][dispersion]") {
    // photons/dispersion.pov: a glass ball of dispersion 1.4 over a floor.
    // Each photon refracted into the ball splits into 7 bands, each with
    // its band's share of the light and bent by its own ior: POV-Ray 3.7
    // stored 279,977 photons, hexant 279,895 when written (without
    // dispersion, 40,058). The image: 89.9% of the pixels within 2 steps,
    // mean 1.47, the caustic's photon noise (without dispersion: 86.1%,
    // mean 5.86, worst 188).
    const auto [image, stored] = still_counting("dispersion", "", "\nphotons stored");
    CHECK(stored == Approx(279977).epsilon(0.01));
    check_agreement(agree(image, read_png(kFolder / "photons" / "dispersion_0.png")), 850, 2.5);
}

TEST_CASE("photons are left in media along their way", "[tracer][photons][media]") {
    // photons/media_photons.pov: a spotlight's beam through a glass ball in
    // a hollow box of scattering media, `photons { media 60, 2 }`. The
    // photons are left every spacing x 2 along their ways in the media
    // after their first surface (at most 60 an interval) and light each
    // media sample as lights from their directions over the gather's
    // sphere (POV-Ray's DepositMediaPhotons and ComputeMediaPhotons). When
    // written: 85.0% of the pixels within 2 steps of POV-Ray's, mean 1.59,
    // worst 58 (the beam's photon noise); media photons stored: POV-Ray
    // 23,040, hexant 26,465 (+15%; at a spacing of 0.02, 372,720 and
    // 411,228, and 96.1% within 2 steps). Without media photons: 40.7%,
    // mean 20.4.
    // (The count's tolerance holds the 15% not yet explained, no more.)
    const auto [image, stored] = still_counting("media_photons", "", "media photons stored");
    CHECK(stored == Approx(23040).epsilon(0.2));
    check_agreement(agree(image, read_png(kFolder / "photons" / "media_photons_0.png")), 800, 2.5);
}

TEST_CASE("media lit through a photon target see that light by photons only",
          "[tracer][photons][media]") {
    // The same without media photons (MediaSteps=0): the box is a target
    // that refracts the spotlight's photons, so a media sample's shadow
    // ray through its surface is dark for that light (POV-Ray's
    // ComputeShadowColour under litObjectIgnoresPhotons, which media that
    // collect photons set): no beam. When written: 99.9% within 2 steps,
    // mean 0.33. Lit by the beam directly (before): 73.2%, mean 20.7.
    const auto [image, stored] =
        still_counting("media_photons", "--declare MediaSteps=0", "media photons stored");
    CHECK(stored == 0.0);
    // (Media's sampling, not the still's: within 2 steps but for the
    // media's adaptive samples' rounding.)
    check_agreement(agree(image, read_png(kFolder / "photons" / "media_photons_none_0.png")), 995,
                    0.5);
}

TEST_CASE("the photon map's noise is reported with the frame's estimate",
          "[tracer][photons][estimate]") {
    // A frame's photons are shot once, so its samples all see the same
    // map: the blocks' estimate cannot see the map's noise, and more
    // samples do not lower it. It is reported beside the estimate: each
    // gather's variance is its photons' terms squared (Poisson points),
    // seen through the layers above, averaged over each pixel's samples.
    // With the radius following the density, its relative size goes as
    // 1 / sqrt(photons gathered): gathering 100 against 20 should lower
    // it by about sqrt(5) = 2.2. When written: 0.236 against 0.0704, 3.35
    // (the sparse gathers of 20 also widen less); 400 gave 0.0288.
    const fs::path scene = fs::temp_directory_path() / "hexant_photon_noise.pov";
    const auto rmse_of = [&](const std::string& photons) {
        {
            std::ofstream text(scene);
            text << "global_settings { " << photons << " }\n"
                 << "camera { location <0, 4, -3> look_at <0, 0, 0.3> angle 50 }\n"
                    "light_source { <-2, 6, 2> rgb 1 }\n"
                    "plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 } }\n"
                    "sphere { <0, 0.7, 0>, 0.7 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }\n"
                    "  interior { ior 1.5 } photons { target refraction on } }\n";
        }
        const fs::path out = fs::temp_directory_path() / "hexant_photon_noise.png";
        const Ran ran = run_command(std::string(HEXANT_BINARY) + " render " + scene.string() +
                                    " -W 64 -H 48 --spp 4 -o " + out.string());
        REQUIRE(ran.ok);
        const std::string key = "the photon map's RMSE ";
        const std::size_t at = ran.said.find(key);
        return at == std::string::npos ? -1.0 : std::stod(ran.said.substr(at + key.size()));
    };
    const double few = rmse_of("photons { spacing 0.01 gather 5, 20 }");
    const double many = rmse_of("photons { spacing 0.01 gather 20, 100 }");
    INFO("gathering 20: " << few << ", 100: " << many);
    CHECK(few > 0.0);
    CHECK(many > 0.0);
    CHECK(few / many > 1.6);
    CHECK(few / many < 5.0);
    CHECK(rmse_of("") == -1.0);  // no photons: nothing said
}
