"""Motion post-processing of paper VII-B: time-warp, smoothing (Eq. 16), silence, resampling."""
