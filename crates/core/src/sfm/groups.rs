//! Which points and frames can take part in a reconstruction, and the groups of frames that
//! can share one frame of reference. Nothing here is fatal: what cannot take part is dropped
//! with the reason, and the rest goes on.
//!
//! The rules, applied until none drops anything more:
//! - a point seen in fewer than 2 of the frames kept is dropped (one image fixes no depth);
//! - a frame that sees fewer than [`MIN_POINTS`] of the points kept is dropped (no camera is
//!   fitted to fewer);
//! - frames are *linked* when both see at least [`LINK`] of the same points kept, and a
//!   *group* is a connected component of the graph on the frames kept with those links (a
//!   chain of links joins two frames that share nothing); a group of fewer than
//!   [`MIN_FRAMES`] frames is dropped (two frames never determine the body, §5);
//! - a point belongs to each group in which at least 2 frames see it (so it is placed in
//!   each, in that group's frame of reference); a point in no group is dropped.
//!
//! Why [`LINK`] = 4: two partial reconstructions come into one frame of reference through
//! the points they share, and it takes four points not in a plane to fix the affine map of
//! space between them (12 unknowns, 3 equations a point); with three, a triangle matches its
//! own reflection, so each side keeps its own mirror (Necker) twin and the joined body is
//! one of two. Groups are therefore reconstructed apart, never as one body. Linking by frame
//! pairs is the rule the chained start of variable projection follows; it is stricter than
//! the bare count in one rare case (four shared points seen by different pairs of frames),
//! which it splits rather than joins. A link is necessary, not sufficient: a group can still
//! be degenerate (too little motion), and the factorisation names that.

use std::collections::VecDeque;

use super::{Observations, MIN_FRAMES, MIN_POINTS};

/// Points two frames must share to be linked (see the module).
pub const LINK: usize = 4;

/// Frames named in one reason at most (the JSON lists every dropped frame on its own).
const NAMED: usize = 5;

/// A point that cannot take part, and why.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct DroppedPoint {
    /// The point's name.
    pub name: String,
    /// Why it was dropped.
    pub why: String,
}

/// A frame that cannot take part, and why.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct DroppedFrame {
    /// The frame, counted from 1.
    pub frame: usize,
    /// Why it was dropped.
    pub why: String,
}

/// A group of linked frames and the points it places (indices into the observations,
/// ascending).
#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    /// The frames.
    pub frames: Vec<usize>,
    /// The points seen in at least 2 of its frames.
    pub points: Vec<usize>,
}

impl Group {
    /// The group's observations: its points in its frames only.
    pub fn observations(&self, obs: &Observations) -> Observations {
        Observations {
            names: self.points.iter().map(|&j| obs.names[j].clone()).collect(),
            frames: self
                .frames
                .iter()
                .map(|&f| self.points.iter().map(|&j| obs.frames[f][j]).collect())
                .collect(),
        }
    }
}

/// The groups, in the order of their first frames, and what was dropped, in the tracks'
/// order.
#[derive(Clone, Debug, PartialEq)]
pub struct Partition {
    /// The groups, each to be reconstructed in its own frame of reference.
    pub groups: Vec<Group>,
    /// The points dropped.
    pub dropped_points: Vec<DroppedPoint>,
    /// The frames dropped.
    pub dropped_frames: Vec<DroppedFrame>,
}

/// The frames that see each point and the points each frame sees, and what is still kept.
struct State {
    by_point: Vec<Vec<usize>>,
    by_frame: Vec<Vec<usize>>,
    point_on: Vec<bool>,
    frame_on: Vec<bool>,
    dropped_points: Vec<(usize, String)>,
    dropped_frames: Vec<(usize, String)>,
}

/// Frame numbers (from 1) as a short list: at most [`NAMED`], then how many more.
fn numbers(frames: &[usize]) -> String {
    let mut s: Vec<String> = frames
        .iter()
        .take(NAMED)
        .map(|f| (f + 1).to_string())
        .collect();
    if frames.len() > NAMED {
        s.push(format!("and {} more", frames.len() - NAMED));
    }
    s.join(", ")
}

/// "1 frame" or "3 frames" (and points alike).
fn count(n: usize, what: &str) -> String {
    format!("{n} {what}{}", if n == 1 { "" } else { "s" })
}

impl State {
    fn new(obs: &Observations) -> State {
        let (k, p) = (obs.frames.len(), obs.names.len());
        let mut by_point = vec![Vec::new(); p];
        let mut by_frame = vec![Vec::new(); k];
        for (f, j, _) in obs.seen() {
            by_point[j].push(f);
            by_frame[f].push(j);
        }
        State {
            by_point,
            by_frame,
            point_on: vec![true; p],
            frame_on: vec![true; k],
            dropped_points: Vec::new(),
            dropped_frames: Vec::new(),
        }
    }

    fn kept_frames(&self, j: usize) -> Vec<usize> {
        self.by_point[j]
            .iter()
            .copied()
            .filter(|&f| self.frame_on[f])
            .collect()
    }

    fn kept_points(&self, f: usize) -> usize {
        self.by_frame[f]
            .iter()
            .filter(|&&j| self.point_on[j])
            .count()
    }

    fn drop_point(&mut self, j: usize) {
        let all = self.by_point[j].len();
        let kept = self.kept_frames(j);
        let why = match (all, kept.len()) {
            (0, _) => "seen in no frame".to_string(),
            (1, _) => format!(
                "seen in 1 frame (frame {}): at least 2 are needed",
                numbers(&self.by_point[j])
            ),
            (_, 0) => format!(
                "none of its {} is kept: at least 2 are needed",
                count(all, "frame")
            ),
            (_, _) => format!(
                "1 of its {} is kept (frame {}): at least 2 are needed",
                count(all, "frame"),
                numbers(&kept)
            ),
        };
        self.point_on[j] = false;
        self.dropped_points.push((j, why));
    }

    fn drop_frame(&mut self, f: usize, why: String) {
        self.frame_on[f] = false;
        self.dropped_frames.push((f, why));
    }

    /// Drop points seen in fewer than 2 kept frames and frames that see fewer than
    /// [`MIN_POINTS`] kept points, each drop lowering the others' counts, to a fixed point
    /// (every observation is visited a bounded number of times).
    fn cascade(&mut self) {
        let mut seen: Vec<usize> = (0..self.by_point.len())
            .map(|j| self.kept_frames(j).len())
            .collect();
        let mut sees: Vec<usize> = (0..self.by_frame.len())
            .map(|f| self.kept_points(f))
            .collect();
        let mut points: VecDeque<usize> = (0..seen.len())
            .filter(|&j| self.point_on[j] && seen[j] < 2)
            .collect();
        let mut frames: VecDeque<usize> = (0..sees.len())
            .filter(|&f| self.frame_on[f] && sees[f] < MIN_POINTS)
            .collect();
        loop {
            if let Some(j) = points.pop_front() {
                self.drop_point(j);
                for &f in &self.by_point[j] {
                    sees[f] -= 1;
                    if self.frame_on[f] && sees[f] + 1 == MIN_POINTS {
                        frames.push_back(f);
                    }
                }
            } else if let Some(f) = frames.pop_front() {
                let all = self.by_frame[f].len();
                let why = if sees[f] == all {
                    format!(
                        "sees {}: at least {MIN_POINTS} are needed",
                        count(all, "point")
                    )
                } else {
                    format!(
                        "{} of its {} kept: at least {MIN_POINTS} are needed",
                        sees[f],
                        count(all, "point")
                    )
                };
                self.drop_frame(f, why);
                for &j in &self.by_frame[f] {
                    seen[j] -= 1;
                    if self.point_on[j] && seen[j] + 1 == 2 {
                        points.push_back(j);
                    }
                }
            } else {
                break;
            }
        }
    }

    /// Each kept frame's group (see the module), by a search from each frame not yet placed,
    /// in the frames' order. Each point keeps a list of its frames not yet placed, pruned as
    /// it is read, so a point seen everywhere is read in full once.
    fn components(&self) -> Vec<Option<usize>> {
        let k = self.by_frame.len();
        let mut group: Vec<Option<usize>> = vec![None; k];
        let mut open: Vec<Vec<usize>> = (0..self.by_point.len())
            .map(|j| {
                if self.point_on[j] {
                    self.kept_frames(j)
                } else {
                    Vec::new()
                }
            })
            .collect();
        let mut shared = vec![0usize; k];
        let (mut touched, mut next) = (Vec::new(), 0);
        for start in 0..k {
            if !self.frame_on[start] || group[start].is_some() {
                continue;
            }
            group[start] = Some(next);
            let mut queue = VecDeque::from([start]);
            while let Some(f) = queue.pop_front() {
                for &j in self.by_frame[f].iter().filter(|&&j| self.point_on[j]) {
                    open[j].retain(|&g| group[g].is_none());
                    for &g in &open[j] {
                        if shared[g] == 0 {
                            touched.push(g);
                        }
                        shared[g] += 1;
                    }
                }
                for g in touched.drain(..) {
                    if shared[g] >= LINK {
                        group[g] = Some(next);
                        queue.push_back(g);
                    }
                    shared[g] = 0;
                }
            }
            next += 1;
        }
        group
    }

    /// Drop the frames of groups smaller than [`MIN_FRAMES`]; whether any was.
    fn drop_small_groups(&mut self, group: &[Option<usize>]) -> bool {
        let members = by_group(group);
        let mut any = false;
        for frames in members.iter().filter(|m| m.len() < MIN_FRAMES) {
            for &f in frames {
                let why = match frames.iter().find(|&&g| g != f) {
                    None => format!(
                        "shares fewer than {LINK} points with every other frame kept"
                    ),
                    Some(&g) => format!(
                        "linked to frame {} only (they share at least {LINK} points, every other frame fewer): two frames never determine the body",
                        g + 1
                    ),
                };
                self.drop_frame(f, why);
                any = true;
            }
        }
        any
    }

    /// The groups each point belongs to (see the module); the points in none are dropped.
    fn place_points(&mut self, group: &[Option<usize>]) -> Vec<Vec<usize>> {
        let mut members = vec![Vec::new(); by_group(group).len()];
        for j in 0..self.by_point.len() {
            if !self.point_on[j] {
                continue;
            }
            let kept = self.kept_frames(j);
            let mut ids: Vec<usize> = kept.iter().filter_map(|&f| group[f]).collect();
            ids.sort_unstable();
            let mut placed = false;
            for w in ids.chunk_by(|a, b| a == b).filter(|w| w.len() >= 2) {
                members[w[0]].push(j);
                placed = true;
            }
            if !placed {
                self.point_on[j] = false;
                self.dropped_points.push((
                    j,
                    format!(
                        "its {} kept ({}) lie in separate groups of frames (frames are linked by {LINK} shared points): no group has 2 of them",
                        count(kept.len(), "frame"),
                        numbers(&kept)
                    ),
                ));
            }
        }
        members
    }
}

/// The frames of each group, by group.
fn by_group(group: &[Option<usize>]) -> Vec<Vec<usize>> {
    let n = group.iter().flatten().max().map_or(0, |g| g + 1);
    let mut out = vec![Vec::new(); n];
    for (f, g) in group.iter().enumerate() {
        if let Some(g) = g {
            out[*g].push(f);
        }
    }
    out
}

/// The groups of the observations and what cannot take part (see the module).
pub fn partition(obs: &Observations) -> Partition {
    let (k, p) = (obs.frames.len(), obs.names.len());
    // complete tracks of enough points in enough frames: one group, nothing dropped
    if k >= MIN_FRAMES && p >= MIN_POINTS && obs.frames.iter().flatten().all(Option::is_some) {
        return Partition {
            groups: vec![Group {
                frames: (0..k).collect(),
                points: (0..p).collect(),
            }],
            dropped_points: Vec::new(),
            dropped_frames: Vec::new(),
        };
    }
    let mut s = State::new(obs);
    let group = loop {
        s.cascade();
        let group = s.components();
        if !s.drop_small_groups(&group) {
            break group;
        }
    };
    // every frame left is linked to one of its group, so it sees LINK ≥ MIN_POINTS points
    // of the group; a point in no group links no frames, so dropping it changes nothing else
    let points = s.place_points(&group);
    let groups = by_group(&group)
        .into_iter()
        .zip(points)
        .map(|(frames, points)| Group { frames, points })
        .collect();
    s.dropped_points.sort_by_key(|d| d.0);
    s.dropped_frames.sort_by_key(|d| d.0);
    Partition {
        groups,
        dropped_points: s
            .dropped_points
            .into_iter()
            .map(|(j, why)| DroppedPoint {
                name: obs.names[j].clone(),
                why,
            })
            .collect(),
        dropped_frames: s
            .dropped_frames
            .into_iter()
            .map(|(f, why)| DroppedFrame { frame: f + 1, why })
            .collect(),
    }
}
