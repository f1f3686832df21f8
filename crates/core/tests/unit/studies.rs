//! Tests of `orthocheck_core::studies`.

mod exact_views;
mod family_samples;
mod joint_fit;
mod noise;
mod points;
mod rounding;
mod view_bounds;
