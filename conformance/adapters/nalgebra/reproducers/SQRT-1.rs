//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause SQRT-1.
//!
//! SQRT-1 (spec/SPEC.md 6, level Extended, eps16: METRIC-1 and METRIC-6, loose bar 256 eps): the
//! rotor square root s of q^ = q/|q| with s^2 = q^ and s.w > 0, (cos(theta/4), sin(theta/4) u);
//! for q^ = -1 any unit pure quaternion (+z is the spec's). nalgebra's square root is
//! Quaternion::sqrt (src/geometry/quaternion.rs:669-674, "Calculates square root") = powf(0.5) =
//! (ln() * 0.5).exp(), with Quaternion::ln (:499-504) = (ln|q|, v.normalize() * acos(w / |q|)):
//!  - acos(w/|q|) is flat near w/|q| = -1: for a rotation delta short of a full turn the half angle
//!    pi - delta/2 comes back with an absolute error of about eps/delta, so s.w = cos(theta/4) ~
//!    delta/4 is wrong in its leading digits (binary64: 2e-9 rad short of 2 pi gives s.w = -1.6e-16
//!    instead of 7.0e-9, 6.3e7 eps);
//!  - v.normalize() of v = 0 is 0/0: the square root of -1 (and of 1) is NaN.
//! (nalgebra has no UnitQuaternion::sqrt; the adapter's rotation is UnitQuaternion::from_quaternion,
//! whose Quaternion is sqrt'ed through Deref, as here.) The log nalgebra's UnitQuaternion::ln uses
//! is atan2-based (after nalgebra#543); Quaternion::ln still takes acos.
//! Upstream: no matching issue found in dimforge/nalgebra (#543, "Using atan2 instead of acos for
//! rotation angles?", changed UnitQuaternion::angle, not Quaternion::ln).
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example SQRT-1
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{Quaternion, UnitQuaternion};

/// The reference root of q = [x, y, z, w] (w < 0 here): s = (|q| + q) / ||q| + q| with |q| + w
/// formed as |v|^2 / (|q| - w) (no cancellation), in binary64; [x, y, z, w].
fn reference(q: &[f64; 4]) -> [f64; 4] {
    let v2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    let n = (v2 + q[3] * q[3]).sqrt();
    let a = if q[3] < 0.0 { v2 / (n - q[3]) } else { n + q[3] };
    let m = (a * a + v2).sqrt();
    [q[0] / m, q[1] / m, q[2] / m, a / m]
}

/// METRIC-1 (sign-free rotation distance) and METRIC-6 (norm defect), the larger, in radians.
fn error(got: &[f64; 4], r: &[f64; 4]) -> f64 {
    let dm = (0..4).map(|i| (got[i] - r[i]).powi(2)).sum::<f64>().sqrt();
    let dp = (0..4).map(|i| (got[i] + r[i]).powi(2)).sum::<f64>().sqrt();
    let norm = got.iter().map(|x| x * x).sum::<f64>().sqrt();
    (4.0 * dm.min(dp).atan2(dm.max(dp))).max((norm - 1.0).abs())
}

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 SQRT-1: Quaternion::sqrt (exp(ln(q)/2), ln through acos(w)) loses the root near a full turn and is NaN for -1");
    println!("call:    UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z)).quaternion().sqrt()");
    // 1. The suite's worst input, binary64 (near a full turn: 2 pi - 1e-9 .. 1e-1).
    let q = [hexf("-0x1.e214bc3be3603p-29"), hexf("-0x1.b4e74484ab0abp-27"), hexf("0x1.44ec7b8d7eea9p-28"), hexf("-0x1.fffffffffffffp-1")];
    let s = UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[0], q[1], q[2])).quaternion().sqrt();
    let got = [s.i, s.j, s.k, s.w];
    let r = reference(&q);
    let e64 = error(&got, &r) / f64::EPSILON;
    println!("input:   q [x, y, z, w] = {} (binary64)", hxs(&q));
    println!("library: {} {}", hxs(&got), dec(&got));
    println!("correct: {} {}  ((|q| + q)/||q| + q|, |q| + w = |v|^2/(|q| - w))", hxs(&r), dec(&r));
    println!("error:   {e64:.3e} eps (METRIC-1 and METRIC-6; eps = 2^-52; loose bar 256 eps)");
    // 2. The suite's worst input, binary32.
    let q32 = [hexf("0x1.599e2cp-15") as f32, hexf("-0x1.19472cp-12") as f32, hexf("0x1.28d9f4p-13") as f32, hexf("-0x1.fffffep-1") as f32];
    let s32 = UnitQuaternion::from_quaternion(Quaternion::new(q32[3], q32[0], q32[1], q32[2])).quaternion().sqrt();
    let got32 = [s32.i as f64, s32.j as f64, s32.k as f64, s32.w as f64];
    let r32 = reference(&[q32[0] as f64, q32[1] as f64, q32[2] as f64, q32[3] as f64]);
    let e32 = error(&got32, &r32) / f32::EPSILON as f64;
    println!("input:   q [x, y, z, w] = {} (binary32)", hxs(&q32.map(|x| x as f64)));
    println!("library: {} {}", hxs(&got32), dec(&got32));
    println!("correct: {} {}", hxs(&r32), dec(&r32));
    println!("error:   {e32:.3e} eps (eps = 2^-23; loose bar 256 eps)");
    // 3. -1: ln divides the zero vector by its norm.
    let m = Quaternion::new(-1.0f64, 0.0, 0.0, 0.0).sqrt();
    println!("input:   q = -1 = [0, 0, 0, -1]");
    println!("library: [{}, {}, {}, {}]", m.i, m.j, m.k, m.w);
    println!("correct: [0, 0, 1, 0], +z (any unit pure quaternion is accepted)");
    if e64 <= 256.0 || e32 <= 256.0 || !m.w.is_nan() {
        println!("DEFECT NOT SHOWN");
        std::process::exit(1);
    }
    println!("DEFECT SHOWN");
}

// ---- helpers: exact hexfloat input and output, the spec's metrics (each reproducer is standalone) ----

/// The exact value of a C99 hexfloat literal such as "-0x1.8p-999" or "0x0.0000000000001p-1022".
fn hexf(s: &str) -> f64 {
    let (neg, body) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s),
    };
    let v = match body {
        "inf" => f64::INFINITY,
        "nan" => f64::NAN,
        _ => {
            let body = body.strip_prefix("0x").expect("a hexfloat starts with 0x");
            let (mant, exp) = body.split_once('p').expect("a hexfloat has an exponent");
            let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
            let mut m: u64 = 0;
            for c in int.chars().chain(frac.chars()) {
                m = m * 16 + c.to_digit(16).expect("hex digit") as u64;
            }
            let mut e: i32 = exp.parse::<i32>().expect("exponent") - 4 * frac.len() as i32;
            let mut v = m as f64; // exact: the literals here have at most 53 significant bits
            while e > 0 {
                let k = e.min(1000);
                v *= 2f64.powi(k);
                e -= k;
            }
            while e < 0 {
                let k = (-e).min(1000);
                v /= 2f64.powi(k); // exact until the last step, which rounds once (subnormals)
                e += k;
            }
            v
        }
    };
    if neg {
        -v
    } else {
        v
    }
}

/// C99 %a of a binary64 value (a binary32 value converted exactly prints the same digits).
fn hx(x: f64) -> String {
    if x.is_nan() {
        return "nan".into();
    }
    let sign = if x.is_sign_negative() { "-" } else { "" };
    if x.is_infinite() {
        return format!("{sign}inf");
    }
    let bits = x.to_bits();
    let (e, m) = (((bits >> 52) & 0x7ff) as i32, bits & ((1u64 << 52) - 1));
    if e == 0 && m == 0 {
        return format!("{sign}0x0p+0");
    }
    let (lead, exp) = if e == 0 { (0, -1022) } else { (1, e - 1023) };
    let frac = format!("{m:013x}");
    let frac = frac.trim_end_matches('0');
    let dot = if frac.is_empty() { String::new() } else { format!(".{frac}") };
    format!("{sign}0x{lead}{dot}p{exp:+}")
}

fn hxs(v: &[f64]) -> String {
    format!("[{}]", v.iter().map(|&x| hx(x)).collect::<Vec<_>>().join(", "))
}

fn dec(v: &[f64]) -> String {
    format!("[{}]", v.iter().map(|x| format!("{x:.12}")).collect::<Vec<_>>().join(", "))
}
