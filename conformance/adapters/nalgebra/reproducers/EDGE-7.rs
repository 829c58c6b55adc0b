//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause EDGE-7.
//!
//! EDGE-7 (spec/SPEC.md 9, class outcome): NaN or +-Inf in an input is DOMAIN_ERROR, every output
//! NaN (a library without a status channel: all outputs NaN, RESULT-2); status OK with some output
//! NaN or +-Inf is ACCEPTABLE (ACC-1 nonfinite_propagation): nalgebra's normalize of (0, Inf, 0, 1)
//! = (0, NaN, 0, 0), try_inverse, products, dual quaternions and isometries all carry the NaN or Inf
//! into their results. An all-finite answer to a non-finite input stays a FAIL, and nalgebra gives
//! one for the axis of a rotation: UnitQuaternion::axis (src/geometry/quaternion.rs:1297-1308) is
//! Unit::try_new(v, 0) (:1307), whose test `sq_norm > min_norm * min_norm` (src/base/unit.rs:151)
//! is false for a NaN norm, so it returns None, documented only as "None if the rotation is zero".
//! axis_angle (:1350) then returns None ("Returns None if the angle is zero": the adapter writes
//! that documented answer, angle 0 about (0, 0, 1)), and ln (:1382-1390) returns Quaternion::zero()
//! (:1388), the logarithm of the identity. UnitQuaternion::from_quaternion (the documented way to
//! get one) of a quaternion with a NaN is all NaN, and of one with an infinity NaN there (Inf/Inf)
//! and 0 elsewhere: axis() answers None for every one of them, and each reads as the identity. The
//! suite's worst input: to_axis_angle of q with a NaN w.
//! Upstream: no matching issue found in dimforge/nalgebra.
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example EDGE-7
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{Quaternion, UnitQuaternion};

fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 EDGE-7: axis_angle of a NaN quaternion is None ('the angle is zero') and ln is 0: the identity's answers");
    // The suite's worst input (to_axis_angle, "NaN in q"), [x, y, z, w] as the report prints it,
    // binary64 and binary32.
    let q = [hexf("-0x1.810a95e48461ap-2"), hexf("0x1.38a1510f9f2a8p-2"), hexf("0x1.bee277da5b067p-1"), hexf("-nan")];
    let q32 = [hexf("-0x1.810a96p-2"), hexf("0x1.38a152p-2"), hexf("0x1.bee278p-1"), hexf("-nan")];

    let u = UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[0], q[1], q[2]));
    let aa = u.axis_angle().map(|(axis, angle)| [axis.x, axis.y, axis.z, angle]);
    let l = u.ln();
    let ln = [l.i, l.j, l.k, l.w];
    let f = q32.map(|x| x as f32);
    let u32 = UnitQuaternion::from_quaternion(Quaternion::new(f[3], f[0], f[1], f[2]));
    let aa32 = u32.axis_angle().map(|(axis, angle)| [axis.x as f64, axis.y as f64, axis.z as f64, angle as f64]);
    let l32 = u32.ln();
    let ln32 = [l32.i as f64, l32.j as f64, l32.k as f64, l32.w as f64];

    // The defect: an answer with no NaN left in it (None, "the angle is zero", or a finite log).
    let shown = !finite(&q) && (aa.map_or(true, |r| finite(&r)) || finite(&ln));
    let shown32 = !finite(&q32) && (aa32.map_or(true, |r| finite(&r)) || finite(&ln32));
    let uq = u.quaternion();
    println!("call:    UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z)).axis_angle(), .axis(), .ln()");
    println!("input:   q [x, y, z, w] = {}   (binary32: {})", hxs(&q), hxs(&q32));
    println!("         from_quaternion: {}", hxs(&[uq.i, uq.j, uq.k, uq.w]));
    println!("library: axis_angle() = {}{}", aa.map_or("None".to_string(), |r| format!("Some(axis {}, angle {})", hxs(&r[..3]), hx(r[3]))),
             if aa.is_none() { "  <-- documented as 'the angle is zero': the identity" } else { "" });
    println!("         axis() = {}", if u.axis().is_none() { "None" } else { "Some(..)" });
    println!("         ln() [x, y, z, w] = {}{}", hxs(&ln), if finite(&ln) { "  <-- zero: the log of the identity" } else { "" });
    println!("         binary32: axis_angle() = {}, ln() = {}", aa32.map_or("None".to_string(), |r| hxs(&r)), hxs(&ln32));
    println!("         (angle() alone = {}: the NaN reaches it)", hx(u.angle()));
    println!("correct: DOMAIN_ERROR: angle NaN, axis [nan, nan, nan], log [nan, nan, nan] (EDGE-7), or some output NaN/Inf (ACC-1 nonfinite_propagation)");
    if !(shown || shown32) {
        println!("DEFECT NOT SHOWN");
        std::process::exit(1);
    }
    println!("error:   an all-finite answer to a non-finite input: the NaN no longer reaches the caller");
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
