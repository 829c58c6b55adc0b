//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause LOG-1.
//!
//! LOG-1 (spec/SPEC.md 8.2, eps16, METRIC-5 in radians): the log of a unit quaternion q =
//! (cos(theta/2), sin(theta/2) u) is (theta/2) u (the log of -q is ACCEPTABLE, ACC-1
//! shorter_arc). UnitQuaternion::ln (src/geometry/quaternion.rs:1382-1389) returns
//! axis() * angle() = theta u, twice the logarithm (its doc says the vector part "corresponds to
//! the axis-angle representation (divided by 2.0)"; Quaternion::ln, :499-504, gives theta/2 u for
//! the same q), so exp(q.ln()) is q^2, not q (EXP-2).
//! Upstream: known, https://github.com/dimforge/nalgebra/issues/1363 ("Unit Quaternion logarithm
//! inconsistent with exp", open).
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example LOG-1
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{Quaternion, UnitQuaternion};

fn main() {
    // The suite's worst input (binary64; w < 0, so the shorter-arc log is that of -q).
    let q = [hexf("-0x1.7c1c2b78f4e3dp-1"), hexf("-0x1.5191472f799d3p-1"), hexf("-0x1.e664eb113e304p-4"), hexf("-0x1.bb4ef507b2433p-8")];
    let unit = UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[0], q[1], q[2]));
    let got: Vec<f64> = unit.ln().imag().iter().copied().collect();

    // Closed form in binary64: log q = atan2(|v|, w) v/|v| (principal), and the log of -q.
    let nq = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    let v: Vec<f64> = q.iter().map(|x| x / nq).collect();
    let nv = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let principal: Vec<f64> = (0..3).map(|i| nv.atan2(v[3]) * v[i] / nv).collect();
    let shorter: Vec<f64> = (0..3).map(|i| -nv.atan2(-v[3]) * v[i] / nv).collect();
    let dist = |a: &[f64], b: &[f64]| (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
    let eps = f64::EPSILON;
    let (e1, e2) = (dist(&got, &principal) / eps, dist(&got, &shorter) / eps);
    let ratio: Vec<f64> = (0..3).map(|i| got[i] / shorter[i]).collect();

    println!("rotorcert reproducer: nalgebra 0.35.0 LOG-1: UnitQuaternion::ln returns theta u, twice the logarithm (theta/2) u, {:.3e} eps", e1.min(e2));
    println!("call:    UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z)).ln().imag()");
    println!("input:   q [x, y, z, w] = {}", hxs(&q));
    println!("library: {} {}", hxs(&got), dec(&got));
    println!("correct: log q = {} {}; log(-q) (ACC-1 shorter_arc) = {} {}", hxs(&principal), dec(&principal), hxs(&shorter), dec(&shorter));
    println!("         library / log(-q) = {}  (a factor 2)", dec(&ratio));
    println!("error:   {e1:.3e} eps against log q, {e2:.3e} eps against log(-q) (METRIC-5; eps = 2^-52; loose bar 256 eps)");
    if e1.min(e2) <= 256.0 {
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
