// hexant against POV-Ray 3.7 on participating media: media in interiors
// and at the top, and the interiors a ray (or its shadow ray) is in (the
// images and the commands that made them: pov_reference/README.md).
#include <string>

#include <catch2/catch.hpp>

#include "pov_reference_compare.hpp"

using namespace hexant::test::pov_reference;

TEST_CASE("media emit, absorb and scatter as in POV-Ray 3.7", "[tracer][pov][media]") {
    // media/emission.pov: emitting media in a hollow glass sphere (a
    // spherical density with turbulence through a colour map, moving with
    // clock) and a box of constant emission. media/scattering.pov: two
    // media in one box, Henyey-Greenstein and isotropic with a bozo
    // density, lit by a spotlight whose cone cuts the rays into lit and
    // unlit intervals, and the box's shadow dimmed by their extinction.
    // media/atmosphere.pov: media { } at the top (Rayleigh), a light with
    // media_attenuation and a cylinder light's beam. The still's
    // tolerance: all six agreed exactly when written (method 3's adaptive
    // sampling is deterministic without jitter); before, media drew
    // nothing (the sphere and box showed the floor through them) and the
    // atmosphere was refused.
    check_stills("media", "emission", {"0", "0.5"});
    check_stills("media", "scattering", {"0", "0.5"});
    check_stills("media", "atmosphere", {"0", "0.5"});
    // media/density_file.pov: an 8-bit .df3 file (blob.df3, made by the
    // script in the README) as the density of emitting media, without
    // interpolation, trilinear and tricubic, turning with clock. The
    // still's tolerance (exact when written; refused before).
    check_stills("media", "density_file", {"0", "0.5"});
    // media/solid_in_media.pov: a glass ball that is not hollow inside
    // glowing media blocks it, a hollow one lets it through. The still's
    // tolerance (exact when written); a shortcut that skipped the solid's
    // inside test where the scene had no fog put the glow inside the
    // glass: 418 pixels off.
    check_stills("media", "solid_in_media", {"0", "0.5"});
    // media/camera_in_media.pov, camera_in_solid.pov: every camera ray
    // starts in the interiors that hold the eye (media; a solid that is
    // not hollow, which keeps fog out). The still's tolerance (exact when
    // written); before, only rays that left the ball before meeting
    // anything were known to start in it: 0.073 and 0.104 mean error.
    check_stills("media", "camera_in_media", {"0", "0.5"});
    check_stills("media", "camera_in_solid", {"0", "0.5"});
}

TEST_CASE("a shadow ray is dimmed by the media of every interior it is in",
          "[tracer][pov][media]") {
    // media/overlapping_media.pov: two overlapping hollow boxes of
    // scattering media (one sliding with clock) and a glass ball that is
    // not hollow; POV-Ray's shadow rays start with the viewing ray's
    // interiors and go in or out of each object met. Before, a shadow ray
    // lost only the media of the object it left, on its last stretch: 18%
    // and 17% of the pixels more than 2 steps off at the two clocks, mean
    // 2.1 and 1.9 steps.
    // Tolerance: where the boxes overlap, the two media sampled together by
    // method 3 still differ from POV-Ray's by a few steps in 23 and 15
    // pixels (0.75% and 0.49%; 11 steps at most, mean 0.08 steps; each box
    // alone is exact): at least 98.5% within 2 steps and a mean below 0.3
    // steps keep the fault this test is for (17% off) far outside.
    for (const char* clock : {"0", "0.5"}) {
        INFO("clock " << clock);
        const Agreement a = agree(
            render(kFolder / "media" / "overlapping_media.pov", "--clock " + std::string(clock),
                   "hexant_pov_overlapping_media", 0, "-W 64 -H 48"),
            read_png(kFolder / "media" / ("overlapping_media_" + std::string(clock) + ".png")));
        INFO("within " << a.within << " of " << a.total << ", mean " << a.mean << ", worst "
                       << a.worst);
        CHECK(a.within >= a.total * 985 / 1000);
        CHECK(a.mean < 0.3);
    }
}

TEST_CASE("a shadowless light lights no media, as in POV-Ray 3.7", "[tracer][pov][media]") {
    // media/shadowless_media.pov: scattering media in a box lit by a
    // shadowless light (POV-Ray's fill light, which its media code leaves
    // out) and a spotlight turning with clock. The still's tolerance
    // (exact when written). Before, the shadowless light lit the media: a
    // third of the pixels off (mean 19 steps).
    check_stills("media", "shadowless_media", {"0", "0.5"});
}

TEST_CASE("a union's interior media reach its members", "[tracer][pov][media]") {
    // media/union_media.pov: absorbing and emitting media in a hollow glass
    // union's own interior (members apart, turning with clock) and in a
    // second union. The still's tolerance (exact when written, one pixel
    // off at clock 0.5). Before, a union split into its members lost its
    // interior's media: 32% and 31% of the pixels off, in silence.
    check_stills("media", "union_media", {"0", "0.5"});
}
