// error: 2:53: blur_samples must be 1 or more
camera { location <0, 0, -5> look_at 0 aperture 0.5 blur_samples 0.5 }
