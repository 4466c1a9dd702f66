// error: 2:53: least must not be above its most
camera { location <0, 0, -5> look_at 0 aperture 0.5 blur_samples 50, 10 }
