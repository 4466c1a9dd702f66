// Dispersion's spectral bands (tracer/spectral_band.hpp): POV-Ray 3.7's
// hue integral, computed from the rule its table was made from, and the
// bands' iors.
#include "tracer/spectral_band.hpp"

#include <catch2/catch.hpp>

using namespace hexant::tracer;

TEST_CASE("the hue integral is POV-Ray 3.7's table", "[tracer][dispersion]") {
    // Entries of SpectralHueIntegral (source/backend/colour/spectral.cpp,
    // 3.7.0.10, printed to 4 decimals): the rule reproduces them within
    // their rounding. A hc running over 380-730 nm instead of 375-740
    // (the spectrum's ends) is off by up to 0.06.
    struct Entry {
        double nm, r, g, b;
    };
    for (const Entry& e : {Entry{380, 0.0009, 0.0000, 0.0038}, Entry{440, 0.0404, 0.0000, 0.2753},
                           Entry{500, 0.0404, 0.0045, 0.7218}, Entry{555, 0.0404, 0.2724, 0.9878},
                           Entry{675, 0.6982, 1.0, 1.0}, Entry{730, 0.9947, 1.0, 1.0}}) {
        INFO(e.nm << " nm");
        const glm::dvec3 h = spectral_hue_integral(e.nm);
        CHECK(h.x == Approx(e.r).margin(1e-4));
        CHECK(h.y == Approx(e.g).margin(1e-4));
        CHECK(h.z == Approx(e.b).margin(1e-4));
    }
    // Between entries it is interpolated linearly, and it is flat outside.
    CHECK(spectral_hue_integral(402.5).z ==
          Approx((spectral_hue_integral(400).z + spectral_hue_integral(405).z) / 2));
    CHECK(spectral_hue_integral(300).z == 0.0);
    CHECK(spectral_hue_integral(800).x == 1.0);
}

TEST_CASE("the bands' hues average to white", "[tracer][dispersion]") {
    // So that white seen through glass stays white: the mean over the
    // bands is the hue integral across the whole spectrum, which (the
    // spectrum being 380-730 nm, the integral's table 375-740) is white to
    // within its tails, 0.0063 at most.
    for (int bands = 2; bands <= 40; ++bands) {
        glm::dvec3 sum(0.0);
        for (int i = 0; i < bands; ++i) sum += SpectralBand::of(i, bands).hue();
        const glm::dvec3 mean = sum / double(bands);
        const glm::dvec3 whole =
            spectral_hue_integral(kSpectralRed) - spectral_hue_integral(kSpectralViolet);
        INFO(bands << " bands");
        for (int c = 0; c < 3; ++c) {
            CHECK(mean[c] == Approx(whole[c]).margin(1e-12));
            CHECK(mean[c] == Approx(1.0).margin(0.0065));
        }
    }
    // Seven bands: violet has no green, red no blue, green is green.
    const glm::dvec3 violet = SpectralBand::of(0, 7).hue(), red = SpectralBand::of(6, 7).hue(),
                     green = SpectralBand::of(3, 7).hue();
    CHECK(violet.y == 0.0);
    CHECK(red.z == 0.0);
    CHECK(green.y > 2.0 * green.x);
    CHECK(green.y > 2.0 * green.z);
}

TEST_CASE("a band's ior is the interior's at the spectrum's middle", "[tracer][dispersion]") {
    // GetDispersionIOR: ior * dispersion^-((wavelength - centre) / width):
    // the middle band of an odd count bends as the written ior, violet
    // more, red less, the ends by sqrt(dispersion).
    CHECK(SpectralBand::of(3, 7).ior(1.5, 1.2) == Approx(1.5));
    CHECK(SpectralBand::of(0, 7).ior(1.5, 1.2) > 1.5);
    CHECK(SpectralBand::of(6, 7).ior(1.5, 1.2) < 1.5);
    const SpectralBand violet_end{kSpectralViolet, 1.0};
    CHECK(violet_end.ior(1.5, 1.2) == Approx(1.5 * std::sqrt(1.2)));
    CHECK_FALSE(SpectralBand{}.monochromatic());
    CHECK(SpectralBand::of(0, 2).monochromatic());
}
