//! Exact numbers across the boundary: Python numbers read exactly (int, `Fraction` and every
//! `numbers.Rational`, `float` as its binary64 value, `str` as the command line reads a token,
//! `Decimal` through `as_integer_ratio`), rationals written as `fractions.Fraction`, and
//! irrational real algebraic numbers as the `Algebraic` class.

use crate::{CasteljauError, guard};
use casteljau::error::Position;
use casteljau::poly::{Poly, RealAlgebraic};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use pyo3::basic::CompareOp;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::sync::GILOnceCell;
use pyo3::types::{PyFloat, PyInt, PyString, PyTuple, PyType};
use std::cmp::Ordering;

static FRACTION: GILOnceCell<Py<PyType>> = GILOnceCell::new();

/// The `fractions.Fraction` class.
pub(crate) fn fraction_type(py: Python<'_>) -> PyResult<&Bound<'_, PyType>> {
    FRACTION.import(py, "fractions", "Fraction")
}

/// A Python int.
pub(crate) fn int(py: Python<'_>, n: &BigInt) -> PyResult<PyObject> {
    if let Some(v) = num_traits::ToPrimitive::to_i64(n) {
        return Ok(v.into_pyobject(py)?.into_any().unbind());
    }
    Ok(n.clone().into_pyobject(py)?.into_any().unbind())
}

/// `Fraction(k)` for small integers `k`, made once (fonts' coordinates are mostly integers, and a
/// `Fraction` is immutable, so one object serves every use).
static SMALL: GILOnceCell<Vec<PyObject>> = GILOnceCell::new();
const SMALL_RANGE: i64 = 1 << 14;

/// A rational as a `fractions.Fraction` (already reduced: the constructor normalises anyway).
pub(crate) fn fraction(py: Python<'_>, r: &BigRational) -> PyResult<PyObject> {
    if r.is_integer()
        && let Some(k) = num_traits::ToPrimitive::to_i64(r.numer())
        && k.abs() < SMALL_RANGE
    {
        let small = SMALL.get_or_try_init(py, || {
            let f = fraction_type(py)?;
            (-SMALL_RANGE + 1..SMALL_RANGE).map(|k| Ok(f.call1((k,))?.unbind())).collect::<PyResult<Vec<_>>>()
        })?;
        return Ok(small[(k + SMALL_RANGE - 1) as usize].clone_ref(py));
    }
    let (n, d) = (int(py, r.numer())?, int(py, r.denom())?);
    Ok(fraction_type(py)?.call1((n, d))?.unbind())
}

/// An exact real: a `Fraction` when rational, else an `Algebraic`.
pub(crate) fn real(py: Python<'_>, x: RealAlgebraic) -> PyResult<PyObject> {
    match x.to_rational() {
        Some(r) => fraction(py, r),
        None => Ok(Py::new(py, Algebraic { value: x })?.into_any()),
    }
}

/// A binary64 value exactly.
pub(crate) fn from_f64(v: f64) -> PyResult<BigRational> {
    BigRational::from_float(v).ok_or_else(|| CasteljauError::new_err(format!("not a finite number: {v}")))
}

/// An integer from a Python object that is an int (or has `__index__`).
fn big_int(ob: &Bound<'_, PyAny>) -> PyResult<BigInt> {
    if let Ok(v) = ob.extract::<i64>() {
        return Ok(BigInt::from(v));
    }
    ob.extract::<BigInt>()
}

/// A Python number read exactly: int; `float` as its binary64 value (`0.1` is
/// `3602879701896397/36028797018963968`); `str` as the command line reads a token (`"1/3"`,
/// `"-0.25"`, `"2e3"`, `"0x1.8p-3"`); an `Algebraic` that is rational; anything with
/// `numerator`/`denominator` (`Fraction`, `numbers.Rational`); anything with
/// `as_integer_ratio` (`Decimal`). `TypeError` for other types, `CasteljauError` for a bad
/// string or a non-finite float.
pub(crate) fn rational(ob: &Bound<'_, PyAny>) -> PyResult<BigRational> {
    if ob.is_instance_of::<PyInt>() {
        return Ok(BigRational::from_integer(big_int(ob)?));
    }
    if let Ok(f) = ob.downcast::<PyFloat>() {
        return from_f64(f.value());
    }
    if let Ok(s) = ob.downcast::<PyString>() {
        let text = s.to_cow()?;
        let token = text.trim();
        return casteljau::num::parse_number(token, Position { line: None, column: 1, token: 1 }).map_err(crate::error);
    }
    if let Ok(a) = ob.downcast::<Algebraic>() {
        return match a.get().value.to_rational() {
            Some(r) => Ok(r.clone()),
            None => Err(CasteljauError::new_err(format!(
                "the irrational number {} where a rational number is needed",
                a.get().value
            ))),
        };
    }
    if let (Ok(n), Ok(d)) = (ob.getattr("numerator"), ob.getattr("denominator")) {
        let (n, d) = (big_int(&n)?, big_int(&d)?);
        if d.is_zero() {
            return Err(CasteljauError::new_err("a rational with denominator 0"));
        }
        return Ok(BigRational::new(n, d));
    }
    if let Ok(f) = ob.getattr("as_integer_ratio") {
        let t = f.call0()?;
        let t = t.downcast::<PyTuple>()?;
        let (n, d) = (big_int(&t.get_item(0)?)?, big_int(&t.get_item(1)?)?);
        return Ok(BigRational::new(n, d));
    }
    Err(PyTypeError::new_err(format!(
        "expected a number (int, Fraction, float or str such as \"1/3\"), not {}",
        ob.get_type().name()?
    )))
}

/// An exact real read from Python: an `Algebraic` as it is, anything else as [`rational`].
pub(crate) fn real_of(ob: &Bound<'_, PyAny>) -> PyResult<RealAlgebraic> {
    if let Ok(a) = ob.downcast::<Algebraic>() {
        return Ok(a.get().value.clone());
    }
    Ok(rational(ob)?.into())
}

/// A real algebraic number, exactly: the root of an integer polynomial isolated in an interval
/// with rational ends. Results that are rational are returned as `Fraction` instead, so an
/// `Algebraic` from casteljau is irrational.
///
/// Comparisons with `int`, `Fraction`, `float` (its exact binary64 value) and other
/// `Algebraic`s are exact; `float(x)` is correctly rounded; `str(x)` is the command line's
/// exact spelling (`7/13 - 1/13*sqrt(10)`, `root 1 of t^3 - 2 in [5/4, 21/16]`).
///
/// >>> import casteljau
/// >>> r = casteljau.Algebraic.roots([-2, 0, 1])     # t² − 2
/// >>> r
/// [Algebraic('-sqrt(2)'), Algebraic('sqrt(2)')]
/// >>> r[1] > 1.4142135623730951, float(r[1])
/// (False, 1.4142135623730951)
/// >>> r[1].polynomial, r[1].isolating_interval
/// ([Fraction(-2, 1), Fraction(0, 1), Fraction(1, 1)], (Fraction(0, 1), Fraction(4, 1)))
#[pyclass(module = "casteljau", name = "Algebraic", frozen)]
pub(crate) struct Algebraic {
    pub(crate) value: RealAlgebraic,
}

/// The other side of a comparison, read exactly; `None` when it is not a number.
enum Other {
    Real(RealAlgebraic),
    /// `+inf` (greater than every real), `-inf`, or NaN (unordered).
    Extended(f64),
}

fn other_of(ob: &Bound<'_, PyAny>) -> Option<Other> {
    if let Ok(f) = ob.downcast::<PyFloat>() {
        let v = f.value();
        if !v.is_finite() {
            return Some(Other::Extended(v));
        }
    }
    real_of(ob).ok().map(Other::Real)
}

#[pymethods]
impl Algebraic {
    /// The distinct real roots of the polynomial `coefficients[0] + coefficients[1]·t + …`
    /// (exact numbers), ascending, each a `Fraction` or an `Algebraic`; with `lo` and `hi`, only
    /// those in `[lo, hi]`.
    #[staticmethod]
    #[pyo3(signature = (coefficients, lo=None, hi=None))]
    fn roots(
        py: Python<'_>,
        coefficients: Vec<Bound<'_, PyAny>>,
        lo: Option<Bound<'_, PyAny>>,
        hi: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Vec<PyObject>> {
        let c = coefficients.iter().map(rational).collect::<PyResult<Vec<_>>>()?;
        let p = Poly::new(c);
        if p.is_zero() {
            return Err(CasteljauError::new_err("the zero polynomial has every number as a root"));
        }
        if p.degree().unwrap_or(0) > 1000 {
            return Err(CasteljauError::new_err(format!(
                "polynomial degree {} exceeds the limit 1000",
                p.degree().unwrap_or(0)
            )));
        }
        let bounds = match (lo, hi) {
            (None, None) => None,
            (Some(a), Some(b)) => Some((rational(&a)?, rational(&b)?)),
            _ => return Err(CasteljauError::new_err("give both lo and hi, or neither")),
        };
        if let Some((a, b)) = &bounds
            && a > b
        {
            return Err(CasteljauError::new_err(format!("empty interval [{a}, {b}]")));
        }
        let roots = crate::run(py, move || {
            Ok(match bounds {
                None => RealAlgebraic::real_roots(&p),
                Some((a, b)) => RealAlgebraic::roots_in(&p, &a, &b),
            })
        })?;
        roots.into_iter().map(|r| real(py, r)).collect()
    }

    /// The polynomial the number is a root of (square-free, primitive, integer coefficients as
    /// `Fraction`s), lowest degree first.
    #[getter]
    fn polynomial(&self, py: Python<'_>) -> PyResult<Vec<PyObject>> {
        self.value.polynomial().iter().map(|c| fraction(py, &BigRational::from_integer(c.clone()))).collect()
    }

    /// An interval `(lo, hi)` with rational ends holding the number and no other root of its
    /// polynomial.
    #[getter]
    fn isolating_interval(&self, py: Python<'_>) -> PyResult<(PyObject, PyObject)> {
        let (lo, hi) = self.value.interval();
        Ok((fraction(py, &lo)?, fraction(py, &hi)?))
    }

    /// An isolating interval `(lo, hi)` narrower than `2**-bits`.
    fn interval(&self, py: Python<'_>, bits: u32) -> PyResult<(PyObject, PyObject)> {
        if bits > 1 << 20 {
            return Err(CasteljauError::new_err(format!("bits {bits} exceeds the limit {}", 1 << 20)));
        }
        let mut x = self.value.clone();
        let (lo, hi) = crate::run(py, move || {
            x.refine(&BigRational::new(BigInt::one(), BigInt::one() << bits));
            Ok(x.interval())
        })?;
        Ok((fraction(py, &lo)?, fraction(py, &hi)?))
    }

    /// The sign: -1, 0 or 1.
    #[getter]
    fn sign(&self) -> i32 {
        match self.value.sign() {
            Ordering::Less => -1,
            Ordering::Equal => 0,
            Ordering::Greater => 1,
        }
    }

    fn __float__(&self) -> PyResult<f64> {
        guard(|| Ok(self.value.to_f64()))
    }

    fn __str__(&self) -> String {
        self.value.to_string()
    }

    fn __repr__(&self) -> String {
        format!("Algebraic('{}')", self.value)
    }

    fn __format__(&self, spec: &str, py: Python<'_>) -> PyResult<PyObject> {
        let f = PyFloat::new(py, self.value.to_f64());
        Ok(f.call_method1("__format__", (spec,))?.unbind())
    }

    fn __bool__(&self) -> bool {
        self.value.sign() != Ordering::Equal
    }

    fn __hash__(&self, py: Python<'_>) -> PyResult<isize> {
        // equal numbers have equal correctly rounded floats; an irrational number equals no
        // float or Fraction, so sharing their hashes is only a collision
        match self.value.to_rational() {
            Some(r) => fraction(py, r)?.bind(py).hash(),
            None => PyFloat::new(py, self.value.to_f64()).hash(),
        }
    }

    fn __neg__(&self, py: Python<'_>) -> PyResult<PyObject> {
        let neg = self.value.map_rational(
            &Poly::new(vec![BigRational::zero(), -BigRational::one()]),
            &Poly::new(vec![BigRational::one()]),
        );
        real(py, neg)
    }

    fn __abs__(&self, py: Python<'_>) -> PyResult<PyObject> {
        if self.value.sign() == Ordering::Less { self.__neg__(py) } else { real(py, self.value.clone()) }
    }

    fn __richcmp__(&self, other: &Bound<'_, PyAny>, op: CompareOp) -> PyResult<PyObject> {
        let py = other.py();
        let Some(o) = other_of(other) else { return Ok(py.NotImplemented()) };
        let ord = match o {
            Other::Extended(v) if v.is_nan() => {
                return Ok(matches!(op, CompareOp::Ne).into_pyobject(py)?.to_owned().into_any().unbind());
            }
            Other::Extended(v) => {
                if v > 0.0 {
                    Ordering::Less
                } else {
                    Ordering::Greater
                }
            }
            Other::Real(r) => guard(|| Ok(self.value.cmp(&r)))?,
        };
        let b = match op {
            CompareOp::Lt => ord == Ordering::Less,
            CompareOp::Le => ord != Ordering::Greater,
            CompareOp::Eq => ord == Ordering::Equal,
            CompareOp::Ne => ord != Ordering::Equal,
            CompareOp::Gt => ord == Ordering::Greater,
            CompareOp::Ge => ord != Ordering::Less,
        };
        Ok(b.into_pyobject(py)?.to_owned().into_any().unbind())
    }
}

/// `_core.rational(x)`: `x` read exactly as a `Fraction` (the package's one reading of numbers).
#[pyfunction(name = "rational")]
fn rational_py(py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<PyObject> {
    fraction(py, &rational(x)?)
}

/// `_core.float_of(x)`: the exact number `x` (Fraction or Algebraic) correctly rounded.
#[pyfunction]
fn float_of(x: &Bound<'_, PyAny>) -> PyResult<f64> {
    if let Ok(a) = x.downcast::<Algebraic>() {
        return Ok(a.get().value.to_f64());
    }
    Ok(casteljau::num::ratio_to_f64(&rational(x)?))
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Algebraic>()?;
    m.add_function(wrap_pyfunction!(rational_py, m)?)?;
    m.add_function(wrap_pyfunction!(float_of, m)?)?;
    Ok(())
}
