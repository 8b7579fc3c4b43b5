//! Patches from a flat control net, and the patch operations with typed results whose
//! `Serialize` is their JSON (exact numbers as strings).
//!
//! ```
//! use casteljau::{num::parse_points, ratio, surface::RationalPatch};
//! let net = parse_points("0 0 0, 1 0 1, 2 0 0, 0 1 1, 1 1 2, 2 1 1", 3, None).unwrap();
//! let p = RationalPatch::from_net(&net, (1, 2), None).unwrap();
//! let e = p.eval_checked(&ratio(1, 2), &ratio(1, 3), &casteljau::work::Budget::unlimited()).unwrap();
//! assert_eq!(e.point.to_string(), "(2/3, 1/2, 17/18)");
//! assert!(e.de_casteljau_u_then_v_and_v_then_u_agree);
//! ```

use super::{MAX_PATCH_DEGREE, RationalPatch};
use crate::error::{Error, Result};
use crate::num::point::Point;
use crate::num::scalar::rat;
use crate::num::serial;
use num_rational::BigRational;
use serde::Serialize;
use serde::ser::{SerializeStruct, Serializer};

/// Most segments [`RationalPatch::contour`] samples per direction.
pub const MAX_CONTOUR_SAMPLES: usize = 1000;

impl Serialize for RationalPatch {
    /// `{"degree": [m, n], "homogeneous": rows of points, "weights": rows}`, exact strings.
    fn serialize<Z: Serializer>(&self, s: Z) -> std::result::Result<Z::Ok, Z::Error> {
        let weights: Vec<Vec<String>> =
            self.weights().iter().map(|r| r.iter().map(|w| w.to_string()).collect()).collect();
        let mut st = s.serialize_struct("RationalPatch", 3)?;
        st.serialize_field("degree", &self.degree())?;
        st.serialize_field("homogeneous", self.homogeneous())?;
        st.serialize_field("weights", &weights)?;
        st.end()
    }
}

/// A parameter direction of a patch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ParameterAxis {
    /// The first parameter (rows).
    U,
    /// The second parameter (columns).
    V,
}

impl ParameterAxis {
    /// `"u"` or `"v"`.
    pub fn as_str(self) -> &'static str {
        match self {
            ParameterAxis::U => "u",
            ParameterAxis::V => "v",
        }
    }
}

/// A patch split in one direction ([`RationalPatch::split`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PatchSplit {
    /// The direction split.
    pub direction: ParameterAxis,
    /// Where.
    #[serde(serialize_with = "serial::string")]
    pub at: BigRational,
    /// The part for `[0, at]`.
    pub first: RationalPatch,
    /// The part for `[at, 1]`.
    pub second: RationalPatch,
}

/// A contour `z = c` of a 3D patch ([`RationalPatch::contour`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PatchContour {
    /// The level `c`.
    #[serde(serialize_with = "serial::string")]
    pub z: BigRational,
    /// The Bernstein coefficients `c_ij` of `F(u, v) = Σ B_i(u) B_j(v) c_ij` (zero on the contour).
    #[serde(serialize_with = "rows")]
    pub bernstein_coefficients: Vec<Vec<BigRational>>,
    /// Sampled segments `[(u, v), (u, v)]` (JSON `[[u, v], [u, v]]`) of the contour in the parameter square, when asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub polyline: Option<Vec<[(f64, f64); 2]>>,
}

fn rows<Z: Serializer>(rows: &[Vec<BigRational>], s: Z) -> std::result::Result<Z::Ok, Z::Error> {
    let r: Vec<Vec<serial::AsString<'_, BigRational>>> =
        rows.iter().map(|r| r.iter().map(serial::AsString).collect()).collect();
    r.serialize(s)
}

impl RationalPatch {
    /// The degree `(m, n)` patch of a row-major net of `(m+1)(n+1)` points with `weights` (all
    /// 1 when `None`).
    ///
    /// # Errors
    /// [`Error::TooLarge`] above 64 (`MAX_PATCH_DEGREE`); [`Error::InvalidArgument`] when the
    /// numbers of points or weights do not match; as [`RationalPatch::new`].
    ///
    /// ```
    /// use casteljau::{num::parse_points, rat, surface::RationalPatch};
    /// let net = parse_points("0 0 0, 1 0 1, 0 1 1, 1 1 0", 3, None).unwrap();
    /// let p = RationalPatch::from_net(&net, (1, 1), Some(&[rat(1), rat(2), rat(1), rat(1)])).unwrap();
    /// assert_eq!(p.weights()[0], vec![rat(1), rat(2)]);
    /// assert!(RationalPatch::from_net(&net, (1, 2), None).is_err()); // needs 6 points
    /// ```
    pub fn from_net(
        points: &[Point<BigRational>],
        degree: (usize, usize),
        weights: Option<&[BigRational]>,
    ) -> Result<Self> {
        let rows = net_rows(points, degree)?;
        let ones;
        let w = match weights {
            Some(w) if w.len() != points.len() => {
                return Err(Error::InvalidArgument {
                    message: format!("{} weights for {} control points", w.len(), points.len()),
                });
            }
            Some(w) => w,
            None => {
                ones = vec![rat(1); points.len()];
                &ones
            }
        };
        RationalPatch::new(rows, w.chunks(degree.1 + 1).map(|r| r.to_vec()).collect())
    }

    /// The degree `(m, n)` patch of a row-major net of `(m+1)(n+1)` homogeneous points.
    ///
    /// # Errors
    /// As [`RationalPatch::from_net`] and [`RationalPatch::from_homogeneous`].
    ///
    /// ```
    /// use casteljau::{num::parse_points, rat, surface::RationalPatch};
    /// let net = parse_points("0 0 0 1, 2 0 2 2, 0 1 1 1, 1 1 0 1", 4, None).unwrap();
    /// let p = RationalPatch::from_homogeneous_net(&net, (1, 1)).unwrap();
    /// assert_eq!(p.weights()[0], vec![rat(1), rat(2)]);
    /// ```
    pub fn from_homogeneous_net(points: &[Point<BigRational>], degree: (usize, usize)) -> Result<Self> {
        RationalPatch::from_homogeneous(net_rows(points, degree)?)
    }

    /// The two parts of the patch split at `at` in `direction`.
    ///
    /// # Errors
    /// As [`RationalPatch::split`] and [`RationalPatch::split`].
    ///
    /// ```
    /// use casteljau::{num::parse_points, ratio, surface::{ParameterAxis, RationalPatch}};
    /// let net = parse_points("0 0 0, 1 0 1, 0 1 1, 1 1 0", 3, None).unwrap();
    /// let p = RationalPatch::from_net(&net, (1, 1), None).unwrap();
    /// let s = p.split(ParameterAxis::U, &ratio(1, 2)).unwrap();
    /// assert_eq!(s.first.homogeneous()[1][0].to_string(), "(0, 1/2, 1/2, 1)");
    /// ```
    pub fn split(&self, direction: ParameterAxis, at: &BigRational) -> Result<PatchSplit> {
        let (first, second) = match direction {
            ParameterAxis::U => self.subdivide_u(at)?,
            ParameterAxis::V => self.subdivide_v(at)?,
        };
        Ok(PatchSplit { direction, at: at.clone(), first, second })
    }

    /// The contour `z = level` of a 3D patch: the Bernstein coefficients of `z(u, v) − level`
    /// times the denominator ([`RationalPatch::contour`]) and, for `samples > 0`, a
    /// polyline sampled on a grid of `min(samples, MAX_CONTOUR_SAMPLES)` cells per direction.
    ///
    /// # Errors
    /// [`Error::NotApplicable`] for a patch of fewer than 3 dimensions.
    ///
    /// ```
    /// use casteljau::{num::parse_points, rat, ratio, surface::RationalPatch};
    /// let net = parse_points("0 0 0, 1 0 1, 0 1 1, 1 1 0", 3, None).unwrap();
    /// let p = RationalPatch::from_net(&net, (1, 1), None).unwrap();
    /// let c = p.contour(&ratio(1, 2), 0).unwrap();
    /// assert_eq!(c.bernstein_coefficients[0], vec![ratio(-1, 2), ratio(1, 2)]);
    /// assert!(c.polyline.is_none());
    /// ```
    pub fn contour(&self, level: &BigRational, samples: usize) -> Result<PatchContour> {
        if self.dim() < 3 {
            return Err(Error::NotApplicable { message: "a contour z = c needs a 3D patch".into() });
        }
        let bernstein_coefficients = self.contour_polynomial(2, level);
        let polyline = (samples > 0).then(|| self.contour_polyline(2, level, samples.min(MAX_CONTOUR_SAMPLES)));
        Ok(PatchContour { z: level.clone(), bernstein_coefficients, polyline })
    }
}

/// The rows of a degree `(m, n)` net.
fn net_rows(points: &[Point<BigRational>], (m, n): (usize, usize)) -> Result<Vec<Vec<Point<BigRational>>>> {
    if m > MAX_PATCH_DEGREE || n > MAX_PATCH_DEGREE {
        return Err(Error::TooLarge { what: "patch degree", value: m.max(n), limit: MAX_PATCH_DEGREE });
    }
    if points.len() != (m + 1) * (n + 1) {
        return Err(Error::InvalidArgument {
            message: format!("a degree ({m}, {n}) patch needs {} points, got {}", (m + 1) * (n + 1), points.len()),
        });
    }
    Ok(points.chunks(n + 1).map(|r| r.to_vec()).collect())
}
