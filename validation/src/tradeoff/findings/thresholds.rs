//! The thresholds the findings read the measured rows by: what counts as
//! grazing, as nearer the truth, and as within the noise.

/// A pixel is grazing where its centre first meets a mirror or glass at
/// a cosine below this (78.5° from the normal): where Schlick's law is
/// furthest from the exact one.
pub const GRAZING_COS: f64 = 0.2;

/// A setting is nearer the truth than the scene's own where its relative
/// RMSE is at most this share of theirs (and its render is seen against
/// theirs): a tenth nearer, as a shortcut must be a tenth faster.
pub const NEARER: f64 = 0.9;

/// A share of the light left out is within the noise where it is at most
/// this many standard deviations (the truth's and the render's own).
pub const NOISE_SIGMAS: f64 = 2.0;
