// Dispersion's spectral bands: an interior's `dispersion_samples` bands
// across the visible spectrum, each refracted by its own ior and carrying
// its own hue (POV-Ray 3.7's SpectralBand, source/backend/colour/
// spectral.h, and Trace::ComputeRefraction, render/trace.cpp).
//
// A ray that took one band (a "monochromatic" ray, POV-Ray's word) keeps
// it on its way: a dispersive surface further on bends it by that band's
// ior and splits it no more.
#pragma once

#include <array>
#include <cmath>

#include <glm/vec3.hpp>

namespace hexant::tracer {

// The spectrum POV-Ray divides into bands, in nm, and its middle, where a
// band's ior is the interior's own.
inline constexpr double kSpectralViolet = 380.0, kSpectralRed = 730.0;
inline constexpr double kSpectralWidth = kSpectralRed - kSpectralViolet;
inline constexpr double kSpectralCentre = (kSpectralViolet + kSpectralRed) / 2.0;

// The integral of each channel's hue from the violet end up to wavelength
// `nm`, normalised to 1 at the red end (POV-Ray's GetHueIntegral).
//
// POV-Ray 3.7 keeps it as a table at 5 nm from 375 to 740 nm, linearly
// interpolated; its comment gives the rule the table was made from, which
// is what is computed here: the running sum, over those 74 points, of the
// hue POV-Ray 3.6 gave a dispersion element (Trace::ComputeDispersion:
// three clipped parabolas in hc, red with a second small bump at the
// violet end), with hc running linearly from 0.03 at 375 nm to 0.964 at
// 740 nm; each channel divided by its sum. This agrees with 3.7's printed
// table within its 4 decimals (tests/tracer/spectral_band_test.cpp).
glm::dvec3 spectral_hue_integral(double nm);

// One band: `wavelength` its middle in nm (0: none, a ray of every
// colour), `width` in nm.
struct SpectralBand {
    double wavelength = 0.0;
    double width = kSpectralWidth;

    // Band `band` of `bands` (0 is violet), as POV-Ray's SpectralBand(i, n).
    static SpectralBand of(int band, int bands) {
        const double width = kSpectralWidth / bands;
        return {kSpectralViolet + width * (band + 0.5), width};
    }
    bool monochromatic() const { return wavelength > 0.0; }

    // The ratio of indices this band sees at a surface where light of
    // the spectrum's middle sees `ior` (the side it leaves over the side
    // it enters) and the ratio of the two sides' dispersions is
    // `dispersion` (POV-Ray's GetDispersionIOR): violet bends more when
    // the dispersion is above 1, by up to sqrt(dispersion) at the end.
    double ior(double ior_ratio, double dispersion_ratio) const {
        return ior_ratio *
               std::pow(dispersion_ratio, -(wavelength - kSpectralCentre) / kSpectralWidth);
    }

    // The colour the band carries (POV-Ray's GetHue): its share of each
    // channel's hue integral over the band, times the number of bands of
    // its width, so that the mean over all bands is white.
    glm::dvec3 hue() const {
        return (spectral_hue_integral(wavelength + width / 2.0) -
                spectral_hue_integral(wavelength - width / 2.0)) *
               (kSpectralWidth / width);
    }
};

}  // namespace hexant::tracer
