//! Geometry of 3D panels for the plot writer: the camera, the axes box, which of the box's
//! faces and edges carry panes and labels, and surface quads in back-to-front order.
//!
//! Pure f64 code. Points live in "box coordinates": the displayed ranges mapped onto a box of
//! proportions [`BOX_ASPECT`] centred on the origin. Nothing here draws, formats text or knows
//! about series: the plot writer turns the projected points into plotters elements.
//!
//! The camera follows matplotlib's `view_init(elev, azim)`: it looks at the box centre from
//! elevation `elev` above the x–y plane and azimuth `azim` around the z axis (0° = from +x),
//! with z pointing up on screen. The projection is orthographic, so parallel box edges stay
//! parallel and tick spacing is uniform along an edge.

/// A point in box coordinates.
pub type P3 = [f64; 3];

/// Box proportions x : y : z, matplotlib's default 3D box aspect.
pub const BOX_ASPECT: [f64; 3] = [4.0, 4.0, 3.0];
/// matplotlib's default view (elevation, azimuth) in degrees, used when a given angle is not finite.
const DEFAULT_VIEW_DEG: (f64, f64) = (30.0, -60.0);
/// Relative slack when testing whether a point is inside the box, so that points exactly on a
/// face survive the rounding of the range mapping.
const INSIDE_SLACK: f64 = 1e-9;
/// Surface shading: brightness of a face seen edge-on to the light; a face facing it is 1.
const AMBIENT: f64 = 0.62;
/// Light direction in camera terms (right, up, toward the viewer): from the upper left, in front.
const LIGHT: P3 = [-0.35, 0.6, 0.72];

/// An orthographic camera around the box centre.
#[derive(Debug, Clone, Copy)]
pub struct View {
    /// Unit vector pointing right on screen.
    right: P3,
    /// Unit vector pointing up on screen.
    up: P3,
    /// Unit vector from the box centre toward the camera.
    toward: P3,
}

impl View {
    /// The camera at `elevation_deg` above the x–y plane and `azimuth_deg` around z.
    pub fn new(elevation_deg: f64, azimuth_deg: f64) -> View {
        let (elevation, azimuth) = if elevation_deg.is_finite() && azimuth_deg.is_finite() {
            (elevation_deg.to_radians(), azimuth_deg.to_radians())
        } else {
            (
                DEFAULT_VIEW_DEG.0.to_radians(),
                DEFAULT_VIEW_DEG.1.to_radians(),
            )
        };
        let (sin_el, cos_el) = elevation.sin_cos();
        let (sin_az, cos_az) = azimuth.sin_cos();
        let toward = [cos_el * cos_az, cos_el * sin_az, sin_el];
        // ẑ × toward, normalised; written from the azimuth alone so that it stays defined when
        // looking straight down or up.
        let right = [-sin_az, cos_az, 0.0];
        let up = cross(toward, right);
        View { right, up, toward }
    }

    /// Screen position of `p`: (right, up), in box units.
    pub fn screen(&self, p: P3) -> (f64, f64) {
        (dot(p, self.right), dot(p, self.up))
    }

    /// Distance of `p` toward the camera: larger is nearer.
    pub fn depth(&self, p: P3) -> f64 {
        dot(p, self.toward)
    }

    /// Brightness in [`AMBIENT`, 1] of a face with corners `c`, lit from a fixed direction
    /// relative to the camera; both sides of the face are lit alike.
    pub fn shade(&self, c: &[P3; 4]) -> f64 {
        let normal = cross(sub(c[2], c[0]), sub(c[3], c[1]));
        let length = dot(normal, normal).sqrt();
        if !(length > 0.0 && length.is_finite()) {
            return 1.0;
        }
        let light = [0, 1, 2]
            .map(|i| LIGHT[0] * self.right[i] + LIGHT[1] * self.up[i] + LIGHT[2] * self.toward[i]);
        let cosine = (dot(normal, light) / (length * dot(light, light).sqrt())).abs();
        AMBIENT + (1.0 - AMBIENT) * cosine
    }

    /// For each axis, whether the box face far from the camera is its high end.
    pub fn far_sides(&self) -> [bool; 3] {
        self.toward.map(|t| t < 0.0)
    }

    /// The three labelled edges: x and y along the floor (the far z face) on the side nearer
    /// the camera, z up the silhouette corner further right on screen.
    pub fn axis_edges(&self) -> [Edge; 3] {
        let far = self.far_sides();
        let x = Edge::new(0, [false, !far[1], far[2]]);
        let y = Edge::new(1, [!far[0], false, far[2]]);
        // The two silhouette corners that are on a back wall.
        let on_far_x = Edge::new(2, [far[0], !far[1], false]);
        let on_far_y = Edge::new(2, [!far[0], far[1], false]);
        let mid_x = |e: &Edge| self.screen(e.midpoint()).0;
        let z = if mid_x(&on_far_y) >= mid_x(&on_far_x) {
            on_far_y
        } else {
            on_far_x
        };
        [x, y, z]
    }
}

/// An edge of the box, parallel to one axis.
#[derive(Debug, Clone, Copy)]
pub struct Edge {
    /// The axis the edge runs along (0 = x, 1 = y, 2 = z).
    pub axis: usize,
    /// The edge's end at the low end of its axis.
    pub from: P3,
    /// The edge's end at the high end of its axis.
    pub to: P3,
}

impl Edge {
    /// The edge along `axis` at the given sides (true = high) of the other two axes.
    fn new(axis: usize, sides: [bool; 3]) -> Edge {
        let mut from = corner(sides);
        let mut to = from;
        from[axis] = -BOX_ASPECT[axis] / 2.0;
        to[axis] = BOX_ASPECT[axis] / 2.0;
        Edge { axis, from, to }
    }

    /// The edge's midpoint.
    pub fn midpoint(&self) -> P3 {
        [0, 1, 2].map(|i| (self.from[i] + self.to[i]) / 2.0)
    }

    /// The point at box coordinate `c` along the edge's axis.
    pub fn at(&self, c: f64) -> P3 {
        let mut p = self.from;
        p[self.axis] = c;
        p
    }
}

/// The box corner at the given sides (true = high end) of each axis.
pub fn corner(sides: [bool; 3]) -> P3 {
    [0, 1, 2].map(|i| {
        let half = BOX_ASPECT[i] / 2.0;
        if sides[i] { half } else { -half }
    })
}

/// The four corners, in order around it, of the face at the `high` (or low) end of `axis`.
pub fn face(axis: usize, high: bool) -> [P3; 4] {
    let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
    [(false, false), (true, false), (true, true), (false, true)].map(|(sa, sb)| {
        let mut sides = [false; 3];
        sides[axis] = high;
        sides[a] = sa;
        sides[b] = sb;
        corner(sides)
    })
}

/// The eight corners of the box.
pub fn corners() -> [P3; 8] {
    std::array::from_fn(|i| corner([i & 1 != 0, i & 2 != 0, i & 4 != 0]))
}

/// Maps a display range `[lo, hi]` of axis `axis` onto the box: `lo` → −aspect/2, `hi` → +aspect/2.
pub fn to_box(axis: usize, v: f64, (lo, hi): (f64, f64)) -> f64 {
    ((v - lo) / (hi - lo) - 0.5) * BOX_ASPECT[axis]
}

/// Whether `p` is inside the box (up to [`INSIDE_SLACK`]); false for non-finite points.
pub fn inside(p: P3) -> bool {
    (0..3).all(|i| p[i].abs() <= BOX_ASPECT[i] / 2.0 * (1.0 + INSIDE_SLACK))
}

/// The part of a segment inside the box.
struct Clipped {
    start: P3,
    end: P3,
    /// The segment starts outside the box.
    entered: bool,
    /// The segment ends outside the box.
    left: bool,
}

/// Liang–Barsky in 3D: the part of segment a→b inside the box, if any.
fn clip_segment(a: P3, b: P3) -> Option<Clipped> {
    if !(a.iter().chain(&b).all(|v| v.is_finite())) {
        return None;
    }
    let d = sub(b, a);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for i in 0..3 {
        let half = BOX_ASPECT[i] / 2.0 * (1.0 + INSIDE_SLACK);
        for (p, q) in [(-d[i], a[i] + half), (d[i], half - a[i])] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| [0, 1, 2].map(|i| a[i] + t * d[i]);
    Some(Clipped {
        start: if t0 > 0.0 { at(t0) } else { a },
        end: if t1 < 1.0 { at(t1) } else { b },
        entered: t0 > 0.0,
        left: t1 < 1.0,
    })
}

/// The drawable parts of the polyline `points`: broken at non-finite points and clipped to
/// the box; pieces have at least two points.
pub fn visible_pieces(points: &[P3]) -> Vec<Vec<P3>> {
    let mut pieces = Vec::new();
    let mut current: Vec<P3> = Vec::new();
    let mut flush = |current: &mut Vec<P3>| {
        if current.len() >= 2 {
            pieces.push(std::mem::take(current));
        } else {
            current.clear();
        }
    };
    for pair in points.windows(2) {
        let Some(clipped) = clip_segment(pair[0], pair[1]) else {
            flush(&mut current);
            continue;
        };
        if clipped.entered {
            flush(&mut current);
        }
        if current.is_empty() {
            current.push(clipped.start);
        }
        current.push(clipped.end);
        if clipped.left {
            flush(&mut current);
        }
    }
    flush(&mut current);
    pieces
}

/// Box coordinates → device pixels: the camera's view scaled and centred to fit a rectangle.
#[derive(Debug, Clone, Copy)]
pub struct Projector {
    /// The camera.
    pub view: View,
    /// Device pixels per box unit.
    scale: f64,
    /// Device position of the screen origin (the box centre's projection).
    origin: (f64, f64),
}

impl Projector {
    /// Fits the whole box, seen by `view`, into the device rectangle `[x0, x1] × [y0, y1]`
    /// (y down), keeping proportions and centring it.
    pub fn fit(view: View, [x0, x1, y0, y1]: [f64; 4]) -> Projector {
        let screen = corners().map(|c| view.screen(c));
        let bounds = |f: fn(&(f64, f64)) -> f64| {
            screen
                .iter()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(v), hi.max(v))
                })
        };
        let (left, right) = bounds(|p| p.0);
        let (bottom, top) = bounds(|p| p.1);
        let scale = ((x1 - x0) / (right - left))
            .min((y1 - y0) / (top - bottom))
            .max(0.0);
        let origin = (
            (x0 + x1) / 2.0 - scale * (left + right) / 2.0,
            (y0 + y1) / 2.0 + scale * (bottom + top) / 2.0,
        );
        Projector {
            view,
            scale,
            origin,
        }
    }

    /// Device position of `p` (y down).
    pub fn px(&self, p: P3) -> (f64, f64) {
        let (right, up) = self.view.screen(p);
        (
            self.origin.0 + self.scale * right,
            self.origin.1 - self.scale * up,
        )
    }
}

/// One cell of a surface mesh.
#[derive(Debug, Clone, Copy)]
pub struct Quad {
    /// Corners in order around the cell, in box coordinates.
    pub corners: [P3; 4],
    /// Index of the surface it belongs to.
    pub surface: usize,
    /// Brightness from [`View::shade`].
    pub shade: f64,
    /// Mean depth of the corners (larger is nearer).
    depth: f64,
}

/// Appends the cells of the row-major `rows × cols` grid `points` (box coordinates) that lie
/// wholly inside the box; `points.len()` must be `rows · cols`.
pub fn push_quads(
    quads: &mut Vec<Quad>,
    view: &View,
    points: &[P3],
    (rows, cols): (usize, usize),
    surface: usize,
) {
    debug_assert_eq!(points.len(), rows * cols);
    for r in 1..rows {
        for c in 1..cols {
            let at = |r: usize, c: usize| points[r * cols + c];
            let corners = [at(r - 1, c - 1), at(r - 1, c), at(r, c), at(r, c - 1)];
            if !corners.iter().all(|&p| inside(p)) {
                continue;
            }
            let depth = corners.iter().map(|&p| view.depth(p)).sum::<f64>() / 4.0;
            quads.push(Quad {
                corners,
                surface,
                shade: view.shade(&corners),
                depth,
            });
        }
    }
}

/// Sorts quads far to near for the painter's algorithm; ties keep their insertion order.
pub fn back_to_front(quads: &mut [Quad]) {
    quads.sort_by(|a, b| a.depth.total_cmp(&b.depth));
}

fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_camera_basis_is_orthonormal_with_z_up() {
        let view = View::new(65.0, -45.0);
        for v in [view.right, view.up, view.toward] {
            assert!((dot(v, v) - 1.0).abs() < 1e-12);
        }
        assert!(dot(view.right, view.up).abs() < 1e-12);
        assert!(dot(view.up, view.toward).abs() < 1e-12);
        assert!(view.up[2] > 0.0);
        // From azimuth −45° the camera is on the +x, −y side: x and y both run to the right.
        assert!(view.right[0] > 0.0 && view.right[1] > 0.0);
        assert_eq!(view.far_sides(), [false, true, false]);
    }

    #[test]
    fn labelled_edges_are_on_the_front_of_the_floor() {
        let view = View::new(65.0, -45.0);
        let [x, y, z] = view.axis_edges();
        let floor = -BOX_ASPECT[2] / 2.0;
        assert!(x.from[2] == floor && x.from[1] < 0.0);
        assert!(y.from[2] == floor && y.from[0] > 0.0);
        assert!(z.from[0] > 0.0 && z.from[1] > 0.0);
        // Both floor edges are at the bottom of the drawing.
        let lowest = corners()
            .map(|c| view.screen(c).1)
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        assert!((view.screen(x.to).1 - lowest).abs() < 1e-12);
    }

    #[test]
    fn segments_clip_to_the_box() {
        let through = clip_segment([-4.0, 0.0, 0.0], [4.0, 0.0, 0.0]).unwrap();
        assert!((through.start[0] + 2.0).abs() < 1e-6 && (through.end[0] - 2.0).abs() < 1e-6);
        assert!(through.entered && through.left);
        assert!(clip_segment([3.0, 3.0, 0.0], [3.0, 4.0, 0.0]).is_none());
        assert!(clip_segment([f64::NAN, 0.0, 0.0], [0.0, 0.0, 0.0]).is_none());
        // In, out, back in, broken at a NaN: three pieces.
        let line = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [1.5, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [f64::NAN; 3],
            [0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let pieces = visible_pieces(&line);
        assert_eq!(pieces.iter().map(Vec::len).collect::<Vec<_>>(), [3, 3, 2]);
    }

    #[test]
    fn quads_are_sorted_far_to_near() {
        let view = View::new(65.0, -45.0);
        let points: Vec<P3> = (0..9)
            .map(|i| [f64::from(i % 3) - 1.0, f64::from(i / 3) - 1.0, 0.0])
            .collect();
        let mut quads = Vec::new();
        push_quads(&mut quads, &view, &points, (3, 3), 0);
        assert_eq!(quads.len(), 4);
        back_to_front(&mut quads);
        assert!(quads.windows(2).all(|w| w[0].depth <= w[1].depth));
        assert!(quads.iter().all(|q| (AMBIENT..=1.0).contains(&q.shade)));
    }
}
