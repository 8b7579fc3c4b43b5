//! Word-sized number theory: binary gcds of `u128`s (and of big integers through one big
//! remainder), exact square roots of words, residues of big integers modulo words, and the
//! extraction of the squares of the primes below 1000 (the spelling rule of
//! [`QuadraticExt::sqrt`](crate::num::QuadraticExt::sqrt)).
//!
//! Hand-written because the hot paths — reducing
//! [`SmallRational`](crate::num::SmallRational)s, the contents of integer polynomials,
//! reductions modulo small primes — need word arithmetic without allocation, and num-bigint's
//! gcd is the bit-by-bit Stein algorithm.

/// `gcd(a, b)` of non-negative numbers (binary; word-sized when both fit 64 bits).
pub(crate) fn gcd_u128(a: u128, b: u128) -> u128 {
    gcd(a, b)
}

/// `gcd(|a|, |b|)`: one big remainder and word gcds when either fits 128 bits (the common case
/// for contents of polynomials), num-bigint's binary gcd otherwise.
pub(crate) fn gcd_big(a: &num_bigint::BigInt, b: &num_bigint::BigInt) -> num_bigint::BigInt {
    use num_bigint::{BigInt, BigUint};
    use num_traits::ToPrimitive;
    let rem = |x: &BigUint, w: u128| -> u128 {
        if w >> 64 == 0 { u128::from(rem_u64(x, w as u64)) } else { (x % w).to_u128().expect("below a u128") }
    };
    let (ma, mb) = (a.magnitude(), b.magnitude());
    let small = |w: u128, other: &BigUint| -> BigInt {
        if w == 0 { BigInt::from(other.clone()) } else { BigInt::from(gcd(w, rem(other, w))) }
    };
    match (ma.to_u128(), mb.to_u128()) {
        (Some(w), _) => small(w, mb),
        (None, Some(w)) => small(w, ma),
        (None, None) => {
            // Euclid's remainder while the sizes differ by more than a word (Stein's algorithm
            // would take a step per bit of the difference), then Stein on the balanced pair
            let (mut big, mut small_one) =
                if ma.bits() >= mb.bits() { (ma.clone(), mb.clone()) } else { (mb.clone(), ma.clone()) };
            while big.bits() > small_one.bits() + 64 {
                let r = &big % &small_one;
                big = std::mem::replace(&mut small_one, r);
                if let Some(w) = small_one.to_u128() {
                    return small(w, &big);
                }
            }
            num_integer::Integer::gcd(&BigInt::from(big), &BigInt::from(small_one))
        }
    }
}

/// `a · b` of reduced rationals, reduced by cross-cancelling `gcd(num a, den b)` and
/// `gcd(num b, den a)` ([`gcd_big`]: one big remainder when the sizes differ, where
/// num-rational's product runs Stein's gcd bit by bit over the larger number). A zero factor
/// gives zero at once. Example: `mul_ratio(10001/10000, 5000/3) = 10001/6` (the unit tests).
pub(crate) fn mul_ratio(a: &num_rational::BigRational, b: &num_rational::BigRational) -> num_rational::BigRational {
    use num_traits::{One, Zero};
    if a.is_zero() || b.is_zero() {
        return num_rational::BigRational::zero();
    }
    let (g1, g2) = (gcd_big(a.numer(), b.denom()), gcd_big(b.numer(), a.denom()));
    let cut = |x: &num_bigint::BigInt, g: &num_bigint::BigInt| if g.is_one() { x.clone() } else { x / g };
    let numer = cut(a.numer(), &g1) * cut(b.numer(), &g2);
    let denom = cut(a.denom(), &g2) * cut(b.denom(), &g1);
    // both factors reduced and cross-cancelled: the product is reduced, its denominator positive
    num_rational::BigRational::new_raw(numer, denom)
}

/// `a + b` of reduced rationals (Knuth's addition: with `g = gcd(den a, den b)`, the sum
/// `t = num a · (den b / g) + num b · (den a / g)` needs only `gcd(t, g)` to be reduced), the
/// gcds by [`gcd_big`]. A zero term gives the other at once. Example: `add_ratio(1/6, 1/3) = 1/2`
/// (the unit tests).
pub(crate) fn add_ratio(a: &num_rational::BigRational, b: &num_rational::BigRational) -> num_rational::BigRational {
    use num_traits::{One, Zero};
    if a.is_zero() {
        return b.clone();
    }
    if b.is_zero() {
        return a.clone();
    }
    let g = gcd_big(a.denom(), b.denom());
    if g.is_one() {
        let numer = a.numer() * b.denom() + b.numer() * a.denom();
        return num_rational::BigRational::new_raw(numer, a.denom() * b.denom());
    }
    let t = a.numer() * (b.denom() / &g) + b.numer() * (a.denom() / &g);
    if t.is_zero() {
        return num_rational::BigRational::zero();
    }
    let g2 = gcd_big(&t, &g);
    let denom = (a.denom() / &g) * (b.denom() / &g2);
    num_rational::BigRational::new_raw(t / g2, denom)
}

/// `gcd(a, b)` of non-negative numbers (binary; word-sized when both fit 64 bits).
fn gcd(a: u128, b: u128) -> u128 {
    if a == 0 || b == 0 {
        return a | b;
    }
    if a == 1 || b == 1 {
        return 1;
    }
    if a >> 64 == 0 && b >> 64 == 0 {
        return gcd64(a as u64, b as u64) as u128;
    }
    // one word-sized argument: one remainder brings the other down to a word
    if a >> 64 == 0 || b >> 64 == 0 {
        let (big, word) = if a >> 64 == 0 { (b, a as u64) } else { (a, b as u64) };
        return gcd64(word, (big % word as u128) as u64) as u128;
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b);
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
        if (a | b) >> 64 == 0 {
            return u128::from(gcd64(a as u64, b as u64)) << shift;
        }
        if b >> 64 == 0 && a >> 64 == 0 {
            return (gcd64(a as u64, b as u64) as u128) << shift;
        }
    }
}

fn gcd64(a: u64, b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b >> b.trailing_zeros());
    // both odd; min/max instead of a branch on the comparison (which mispredicts half the time)
    while a != b {
        let (lo, hi) = (a.min(b), a.max(b));
        let diff = hi - lo;
        a = lo;
        b = diff >> diff.trailing_zeros();
    }
    a << shift
}

/// `√n` when `n` is a perfect square: residues mod 64 and 63 reject most non-squares at once,
/// then a float estimate with one Newton step and an exact ±1 correction.
pub(crate) fn square_root(n: u128) -> Option<u128> {
    const SQ64: u64 = {
        let mut m = 0u64;
        let mut i = 0;
        while i < 64 {
            m |= 1 << ((i * i) % 64);
            i += 1;
        }
        m
    };
    const SQ63: u64 = {
        let mut m = 0u64;
        let mut i = 0;
        while i < 63 {
            m |= 1 << ((i * i) % 63);
            i += 1;
        }
        m
    };
    if SQ64 >> (n % 64) & 1 == 0 || SQ63 >> (n % 63) & 1 == 0 {
        return None;
    }
    let r = isqrt(n);
    (r * r == n).then_some(r)
}

/// `⌊√n⌋`.
fn isqrt(n: u128) -> u128 {
    if n < 2 {
        return n;
    }
    let mut r = (n as f64).sqrt() as u128;
    if n >> 100 != 0 {
        r = (r + n / r) / 2; // the float estimate is off by up to ~2^12 here
    }
    while r.checked_mul(r).is_none_or(|s| s > n) {
        r -= 1;
    }
    while (r + 1).checked_mul(r + 1).is_some_and(|s| s <= n) {
        r += 1;
    }
    r
}

/// Odd primes `p` below 1000 with `p²`, their inverses mod 2^128 and mod 2^64, and
/// `u128::MAX / p`, `u64::MAX / p`: `p | m` iff `m · p⁻¹ mod 2^w ≤ (2^w − 1) / p` (one
/// multiplication per prime, no division).
struct OddPrime {
    p: u128,
    inv: u128,
    limit: u128,
    inv64: u64,
    limit64: u64,
}

const ODD_PRIMES: [OddPrime; 167] = {
    let mut out = [const { OddPrime { p: 0, inv: 0, limit: 0, inv64: 0, limit64: 0 } }; 167];
    let mut n = 3u128;
    let mut k = 0;
    while k < 167 {
        let mut prime = true;
        let mut q = 3;
        while q * q <= n {
            if n.is_multiple_of(q) {
                prime = false;
                break;
            }
            q += 2;
        }
        if prime {
            // Newton's iteration doubles the correct low bits: 3 → 6 → … → 192 ≥ 128
            let mut inv = n;
            let mut i = 0;
            while i < 6 {
                inv = inv.wrapping_mul(2u128.wrapping_sub(n.wrapping_mul(inv)));
                i += 1;
            }
            out[k] = OddPrime { p: n, inv, limit: u128::MAX / n, inv64: inv as u64, limit64: u64::MAX / n as u64 };
            k += 1;
        }
        n += 2;
    }
    out
};

/// The odd primes below 1000 (as [`ODD_PRIMES`]) with their inverses mod 2^64 and
/// `u64::MAX / p`, packed for the word-sized loop of [`extract_small_squares`].
const ODD_PRIMES64: [(u64, u64, u64); 167] = {
    let mut out = [(0u64, 0u64, 0u64); 167];
    let mut k = 0;
    while k < 167 {
        out[k] = (ODD_PRIMES[k].p as u64, ODD_PRIMES[k].inv64, ODD_PRIMES[k].limit64);
        k += 1;
    }
    out
};

/// `(k, m)` with `n = k²·m` and `m` free of the squares of primes below 1000 — the square
/// extraction of [`QuadraticExt::sqrt`](crate::num::QuadraticExt::sqrt) for `BigRational`,
/// on words (64-bit words once `n` fits one).
pub(crate) fn extract_small_squares(mut n: u128) -> (u128, u128) {
    let mut k = 1u128;
    if n == 0 {
        return (1, 0);
    }
    let twos = n.trailing_zeros();
    k <<= twos / 2;
    n >>= twos - twos % 2;
    let (k2, m) = extract_small_squares_from(n, 0);
    (k * k2, m)
}

/// The odd part of [`extract_small_squares`], from the `from`-th odd prime on.
fn extract_small_squares_from(mut n: u128, from: usize) -> (u128, u128) {
    let mut k = 1u128;
    for (j, op) in ODD_PRIMES.iter().enumerate().skip(from) {
        if n >> 64 == 0 {
            let (k64, m) = extract_small_squares64(n as u64, j);
            return (k * k64, m as u128);
        }
        loop {
            let q = n.wrapping_mul(op.inv);
            if q > op.limit {
                break;
            }
            // p | n; p² | n?
            let q2 = q.wrapping_mul(op.inv);
            if q2 > op.limit {
                break;
            }
            n = q2;
            k *= op.p;
        }
    }
    (k, n)
}

/// Products of consecutive odd primes below 1000, each below 2^63, with the index range of its
/// primes in [`ODD_PRIMES`]: one remainder of a big number per group, then word arithmetic.
const PRIME_GROUPS: ([(u64, usize, usize); 167], usize) = {
    let mut out = [(0u64, 0usize, 0usize); 167];
    let (mut g, mut k) = (0, 0);
    while k < 167 {
        let (mut prod, start) = (1u64, k);
        while k < 167 && (prod as u128) * ODD_PRIMES[k].p < 1 << 63 {
            prod *= ODD_PRIMES[k].p as u64;
            k += 1;
        }
        out[g] = (prod, start, k);
        g += 1;
    }
    (out, g)
};

/// `n mod m` for `m < 2^64`, from the 64-bit digits (most significant first), without allocating.
pub(crate) fn rem_u64(n: &num_bigint::BigUint, m: u64) -> u64 {
    n.iter_u64_digits().rev().fold(0u64, |r, d| ((u128::from(r) << 64 | u128::from(d)) % u128::from(m)) as u64)
}

/// `n mod m` in `[0, m)` for a signed `n` and `m < 2^64` ([`rem_u64`] of the magnitude, negated
/// modulo `m` for a negative `n`).
pub(crate) fn residue(n: &num_bigint::BigInt, m: u64) -> u64 {
    let r = rem_u64(n.magnitude(), m);
    if n.sign() == num_bigint::Sign::Minus && r != 0 { m - r } else { r }
}

/// `n mod m` in `[0, m)` for a signed `n` and `m < 2^32`, in `u64` operations (no 128-bit
/// division): the magnitude's two words combined with `2^64 mod m`, negated modulo `m` for a
/// negative `n`.
#[inline]
pub(crate) fn residue_i128(n: i128, m: u64) -> u64 {
    debug_assert!(m > 0 && m >> 32 == 0);
    let mag = n.unsigned_abs();
    let (hi, lo) = ((mag >> 64) as u64, mag as u64);
    let base = (u64::MAX % m + 1) % m; // 2^64 mod m
    let r = ((hi % m) * base + lo % m) % m;
    if n < 0 && r != 0 { m - r } else { r }
}

/// [`extract_small_squares`] of a big number: `(k, m)` with `n = k²·m` and `m` free of the
/// squares of primes below 1000 (the rule of
/// [`QuadraticExt::sqrt`](crate::num::QuadraticExt::sqrt)).
/// Divisibility is read from one remainder per group of primes ([`PRIME_GROUPS`]), not one big
/// division per prime.
pub(crate) fn extract_small_squares_big(n: &num_bigint::BigUint) -> (num_bigint::BigUint, num_bigint::BigUint) {
    use num_bigint::BigUint;
    use num_traits::{ToPrimitive, Zero};
    if let Some(w) = n.to_u128() {
        let (k, m) = extract_small_squares(w);
        return (BigUint::from(k), BigUint::from(m));
    }
    let mut m = n.clone();
    let mut k = BigUint::from(1u32);
    if m.is_zero() {
        return (k, m);
    }
    let twos = m.trailing_zeros().unwrap_or(0);
    k <<= twos / 2;
    m >>= twos - twos % 2;
    let (groups, count) = PRIME_GROUPS;
    for &(prod, start, end) in &groups[..count] {
        let r = rem_u64(&m, prod);
        for op in &ODD_PRIMES[start..end] {
            let p = op.p as u64;
            if !r.is_multiple_of(p) {
                continue;
            }
            // p | m: divide out p² while it divides (m changes, so test on m itself)
            let square = BigUint::from(p * p);
            while rem_u64(&m, p * p) == 0 {
                m /= &square;
                k *= p;
            }
            if let Some(w) = m.to_u128() {
                // the rest fits a word: finish there, from the next prime on
                let next = ODD_PRIMES.iter().position(|o| o.p as u64 > p).unwrap_or(167);
                let (k2, m2) = extract_small_squares_from(w, next);
                return (k * BigUint::from(k2), BigUint::from(m2));
            }
        }
    }
    (k, m)
}

/// [`extract_small_squares`] of a word from the `from`-th odd prime on: one multiplication and
/// one comparison per prime while no prime divides `n` (the common case).
fn extract_small_squares64(mut n: u64, from: usize) -> (u128, u64) {
    let mut k = 1u128;
    for &(p, inv, limit) in &ODD_PRIMES64[from..] {
        let q = n.wrapping_mul(inv);
        if q <= limit {
            // p | n: divide out p² while it divides
            let mut q = q;
            loop {
                let q2 = q.wrapping_mul(inv);
                if q2 > limit {
                    break;
                }
                n = q2;
                k *= p as u128;
                q = n.wrapping_mul(inv);
                if q > limit {
                    break;
                }
            }
        }
    }
    (k, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ratio_products_and_sums_match_num_rational() {
        use crate::num::scalar::ratio;
        use num_bigint::BigInt;
        assert_eq!(mul_ratio(&ratio(10001, 10000), &ratio(5000, 3)), ratio(10001, 6));
        assert_eq!(add_ratio(&ratio(1, 6), &ratio(1, 3)), ratio(1, 2));
        let big = |k: u32, d: i64| num_rational::BigRational::new(BigInt::from(10001).pow(k), BigInt::from(d).pow(k));
        let xs = [ratio(0, 1), ratio(-3, 7), ratio(1, 1), big(40, 10000), big(3, -12), -big(50, 6), big(30, 1)];
        for a in &xs {
            for b in &xs {
                assert_eq!(mul_ratio(a, b), a * b, "{a} · {b}");
                assert_eq!(add_ratio(a, b), a + b, "{a} + {b}");
                assert_eq!(add_ratio(a, &-b), a - b, "{a} - {b}");
            }
        }
        // unbalanced and balanced big gcds
        let (p, q) = (BigInt::from(10001).pow(500) * 6, BigInt::from(3).pow(300) * 4);
        assert_eq!(gcd_big(&p, &q), num_integer::Integer::gcd(&p, &q));
        assert_eq!(gcd_big(&(&p * 35), &(&p * 21)), &p * 7);
    }

    #[test]
    fn square_roots_of_words_are_exact() {
        for r in [0u128, 1, 2, 3, 1 << 20, (1 << 63) - 25, u64::MAX as u128] {
            assert_eq!(square_root(r * r), Some(r), "{r}");
            if r > 1 {
                assert_eq!(square_root(r * r - 1), None);
                assert_eq!(isqrt(r * r - 1), r - 1);
                assert_eq!(square_root(r * r + 1), None);
            }
        }
        assert_eq!(isqrt(u128::MAX), u64::MAX as u128);
    }

    /// Word residues and gcds against big-integer arithmetic, extremes included.
    #[test]
    fn word_residues_and_gcds_match_big_integers() {
        let mut next = crate::num::xorshift(0x7E51_DDE5_0F12_8B17);
        let mut values: Vec<i128> = vec![0, 1, -1, i128::MAX, i128::MIN, i128::MIN + 1, 1 << 64, -(1 << 64)];
        for k in 0..400 {
            let v = ((u128::from(next()) << 64 | u128::from(next())) >> (1 + k % 120)) as i128;
            values.extend([v, -v]);
        }
        for &v in &values {
            for m in [3u64, 47 * 53, 111_546_435, 58_642_669, (1 << 31) - 1, 4_294_967_291] {
                assert_eq!(residue_i128(v, m), residue(&num_bigint::BigInt::from(v), m), "{v} mod {m}");
            }
        }
        for _ in 0..400 {
            let (a, b) = (u128::from(next()) << (next() % 64), u128::from(next()) << (next() % 64));
            let expected = num_integer::Integer::gcd(&num_bigint::BigUint::from(a), &num_bigint::BigUint::from(b));
            assert_eq!(num_bigint::BigUint::from(gcd_u128(a, b)), expected, "gcd({a}, {b})");
        }
    }

    #[test]
    fn small_squares_are_extracted_like_the_big_route() {
        for (n, k, m) in
            [(12u128, 2u128, 3u128), (2 * 997 * 997, 997, 2), (1009 * 1009 * 3, 1, 1009 * 1009 * 3), (1, 1, 1)]
        {
            assert_eq!(extract_small_squares(n), (k, m), "{n}");
        }
    }
}

#[cfg(test)]
mod big_square_tests {
    use super::*;
    use num_bigint::BigUint;
    use num_traits::{One, Zero};

    /// The rule as first written: divide out k² for every k from 2 to 999.
    fn naive(n: &BigUint) -> (BigUint, BigUint) {
        let (mut k, mut m) = (BigUint::one(), n.clone());
        if m.is_zero() {
            return (k, m);
        }
        for j in 2u32..1000 {
            let jj = BigUint::from(j * j);
            while (&m % &jj).is_zero() {
                m /= &jj;
                k *= j;
            }
        }
        (k, m)
    }

    #[test]
    fn big_square_extraction_equals_the_naive_rule() {
        let mut next = crate::num::xorshift(0x2545_F491_4F6C_DD1D);
        for _ in 0..300 {
            // products of small primes (some squared), a large prime-ish part, powers of two
            let mut n = BigUint::from(next() | 1) * BigUint::from(next());
            for _ in 0..(next() % 6) {
                let p = [3u64, 5, 7, 11, 997, 991, 2, 9, 25][(next() % 9) as usize];
                n *= p * p;
            }
            if next().is_multiple_of(3) {
                n *= BigUint::from(next()) * BigUint::from(next());
            }
            assert_eq!(extract_small_squares_big(&n), naive(&n), "{n}");
        }
        assert_eq!(extract_small_squares_big(&BigUint::zero()), (BigUint::one(), BigUint::zero()));
    }
}
