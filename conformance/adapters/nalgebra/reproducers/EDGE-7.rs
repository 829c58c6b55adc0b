//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause EDGE-7.
//!
//! EDGE-7 (spec/SPEC.md 9, class outcome): NaN or +-Inf in an input is DOMAIN_ERROR, every output
//! NaN (a library without a status channel: all outputs NaN, RESULT-2). nalgebra checks no input
//! for finiteness: Quaternion::normalize (coords / norm(), src/base/norm.rs) of (0, Inf, 0, 1) is
//! (0, NaN, 0, 0); Quaternion * Quaternion with an infinite factor gives infinities;
//! Quaternion::try_inverse of it returns Some((0, NaN, 0, 0)); DualQuaternion::normalize of an
//! infinite dual part returns it with the real part intact; UnitQuaternion::axis_angle of a NaN
//! quaternion returns None, documented as "the angle is zero".
//! Upstream: no matching issue found in dimforge/nalgebra.
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example EDGE-7
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{DualQuaternion, Quaternion};

fn all_nan(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_nan())
}

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 EDGE-7: non-finite input gives partly finite output with no error (normalize, try_inverse, *, DualQuaternion::normalize)");
    let mut shown = false;
    let inf = f64::INFINITY;
    // EX-EDGE-7-b: normalize((0, Inf, 0, 1)).
    let q = [0.0, inf, 0.0, 1.0];
    let qq = Quaternion::new(q[3], q[0], q[1], q[2]);
    let n = qq.normalize();
    let got = [n.i, n.j, n.k, n.w];
    shown |= !all_nan(&got);
    println!("call:    Quaternion::new(w, x, y, z).normalize()   (f64; f32 alike)");
    println!("input:   q [x, y, z, w] = {}   (EX-EDGE-7-b)", hxs(&q));
    println!("library: {}{}", hxs(&got), if !all_nan(&got) { "  <-- not all NaN: status OK" } else { "" });
    let inv = qq.try_inverse().map(|r| [r.i, r.j, r.k, r.w]);
    if let Some(r) = inv {
        shown |= !all_nan(&r);
    }
    println!("call:    Quaternion::new(w, x, y, z).try_inverse()");
    println!("library: {:?}", inv.map(|r| hxs(&r)));
    let p = qq * Quaternion::new(0.9, 0.1, 0.2, 0.3);
    let got = [p.i, p.j, p.k, p.w];
    shown |= !all_nan(&got);
    println!("call:    q * Quaternion::new(0.9, 0.1, 0.2, 0.3)");
    println!("library: {}", hxs(&got));
    // a dual quaternion with an infinite dual part.
    let d = [0.0, 0.0, 0.0, 1.0, inf, 0.0, 0.0, 0.0];
    let n = DualQuaternion::from_real_and_dual(Quaternion::new(d[3], d[0], d[1], d[2]), Quaternion::new(d[7], d[4], d[5], d[6])).normalize();
    let got = [n.real.i, n.real.j, n.real.k, n.real.w, n.dual.i, n.dual.j, n.dual.k, n.dual.w];
    shown |= !all_nan(&got);
    println!("call:    DualQuaternion::from_real_and_dual(real, dual).normalize()");
    println!("input:   d [real xyzw, dual xyzw] = {}", hxs(&d));
    println!("library: {}", hxs(&got));
    println!("correct: DOMAIN_ERROR: every output NaN (EDGE-7; nalgebra has no error channel here)");
    println!("{}", if shown { "DEFECT SHOWN" } else { "DEFECT NOT SHOWN" });
    std::process::exit(if shown { 0 } else { 1 });
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
