//! Tracks that may have gaps: a point may be absent from some frames.

use nalgebra::Vector2;

use super::{Error, MIN_FRAMES, MIN_POINTS};
use crate::model::Tracks;

/// Image points with gaps: `frames[i][j]` is point `j` in frame `i`, `None` where unseen.
#[derive(Clone, Debug, PartialEq)]
pub struct Observations {
    /// Point names, one per column.
    pub names: Vec<String>,
    /// Frames, each with one optional image point per name.
    pub frames: Vec<Vec<Option<Vector2<f64>>>>,
}

impl Observations {
    /// Complete tracks as observations.
    pub fn from_tracks(t: &Tracks) -> Observations {
        Observations::seen_where(t, |_, _| true)
    }

    /// The tracks' images where `seen(frame, point)` holds (indices), gaps elsewhere.
    pub fn seen_where(t: &Tracks, seen: impl Fn(usize, usize) -> bool) -> Observations {
        Observations {
            names: t.names.clone(),
            frames: t
                .frames
                .iter()
                .enumerate()
                .map(|(f, row)| {
                    row.iter()
                        .enumerate()
                        .map(|(j, y)| seen(f, j).then_some(*y))
                        .collect()
                })
                .collect(),
        }
    }

    /// The tracks, when no point is missing from any frame.
    pub fn complete(&self) -> Option<Tracks> {
        let frames: Option<Vec<Vec<Vector2<f64>>>> = self
            .frames
            .iter()
            .map(|f| f.iter().copied().collect())
            .collect();
        Tracks::new(self.names.clone(), frames?).ok()
    }

    /// Every observation: (frame, point, image).
    pub fn seen(&self) -> impl Iterator<Item = (usize, usize, Vector2<f64>)> + '_ {
        self.frames.iter().enumerate().flat_map(|(i, f)| {
            f.iter()
                .enumerate()
                .filter_map(move |(j, y)| y.map(|y| (i, j, y)))
        })
    }

    /// The number of observations.
    pub fn count(&self) -> usize {
        self.frames.iter().flatten().filter(|y| y.is_some()).count()
    }

    /// Each point's views: (frame, image), frames ascending.
    pub fn by_point(&self) -> Vec<Vec<(usize, Vector2<f64>)>> {
        (0..self.names.len())
            .map(|j| {
                (0..self.frames.len())
                    .filter_map(|f| self.frames[f][j].map(|y| (f, y)))
                    .collect()
            })
            .collect()
    }

    /// The observations in the frames `keep` (indices, in the order given).
    pub fn select_frames(&self, keep: &[usize]) -> Observations {
        Observations {
            names: self.names.clone(),
            frames: keep.iter().map(|&f| self.frames[f].clone()).collect(),
        }
    }

    /// The observations of the points `keep` (indices, in the order given).
    pub fn select_points(&self, keep: &[usize]) -> Observations {
        Observations {
            names: keep.iter().map(|&j| self.names[j].clone()).collect(),
            frames: self
                .frames
                .iter()
                .map(|f| keep.iter().map(|&j| f[j]).collect())
                .collect(),
        }
    }

    /// At least [`MIN_POINTS`] points in at least [`MIN_FRAMES`] frames.
    pub fn check_counts(&self) -> Result<(), Error> {
        self.check_counts_of(self.frames.len())
    }

    /// [`Observations::check_counts`] for these points in `frames` frames.
    pub(super) fn check_counts_of(&self, frames: usize) -> Result<(), Error> {
        if frames < MIN_FRAMES {
            return Err(Error::TooFewFrames { frames });
        }
        if self.names.len() < MIN_POINTS {
            return Err(Error::TooFewPoints {
                points: self.names.len(),
            });
        }
        Ok(())
    }
}

impl From<&Tracks> for Observations {
    fn from(t: &Tracks) -> Observations {
        Observations::from_tracks(t)
    }
}
