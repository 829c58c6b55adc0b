//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause EDGE-2.
//!
//! EDGE-2 (spec/SPEC.md 9): rotation angles (and differences) from 1e-9 to 1e-3 rad are handled
//! within the operation's own class, with no 0/0 and no NaN. UnitDualQuaternion::try_sclerp
//! (src/geometry/dual_quaternion.rs:665-727) takes acos of the scalar part of the relative motion
//! a* b (:699-700); the product of two unit dual quaternions rounds that scalar to 1 + 2^-52 for
//! poses 2.5e-8 rad apart, whose vector part is still above the |v|^2 <= eps cut (:689), and
//! acos(1 + 2^-52) = NaN: sclerp returns all NaN (read as a refusal, DOMAIN_ERROR) for an ordinary
//! input. Same clause, other calls (their own reproducers): UnitQuaternion::slerp's
//! sqrt(1 - c^2) (SLERP-1.rs, 1e8 eps at 1e-8 rad) and UnitQuaternion::ln's factor 2 (LOG-1.rs).
//! Upstream: no matching issue found in dimforge/nalgebra.
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example EDGE-2
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{DualQuaternion, Quaternion, UnitDualQuaternion};

fn unit(d: &[f64]) -> UnitDualQuaternion<f64> {
    UnitDualQuaternion::new_normalize(DualQuaternion::from_real_and_dual(
        Quaternion::new(d[3], d[0], d[1], d[2]),
        Quaternion::new(d[7], d[4], d[5], d[6]),
    ))
}

fn main() {
    // The suite's input (angle family 1e-9 .. 1e-3, binary64): poses 2.5e-8 rad apart.
    let a: Vec<f64> = ["-0x1.a2b979f857335p-2", "-0x1.2cd51397e45bfp-1", "-0x1.51156ced09f97p-2", "0x1.3b491c0d32399p-1", "0x1.7c591c5a027d8p-4", "0x1.8b3300f3e1607p-7", "-0x1.1dd64d5a0bca8p-6", "0x1.0580753e35bfdp-4"].iter().map(|s| hexf(s)).collect();
    let b: Vec<f64> = ["-0x1.a2b97b0412f08p-2", "-0x1.2cd513860eda9p-1", "-0x1.51156cd1481dfp-2", "0x1.3b491bccbd285p-1", "0x1.7c591c23cb92bp-4", "0x1.8b32fe84ac9c8p-7", "-0x1.1dd64e089f4a2p-6", "0x1.0580758fda78ap-4"].iter().map(|s| hexf(s)).collect();
    let t = hexf("0x1.8abf158a1625dp-1");
    let (ua, ub) = (unit(&a), unit(&b));
    let rel = ua.as_ref().conjugate() * ub.as_ref();
    let r = ua.sclerp(&ub, t);
    let dq = r.dual_quaternion();
    let got = [dq.real.i, dq.real.j, dq.real.k, dq.real.w, dq.dual.i, dq.dual.j, dq.dual.k, dq.dual.w];
    let angle = metric1(&a[..4], &b[..4]);
    let shown = got.iter().any(|x| x.is_nan());

    println!("rotorcert reproducer: nalgebra 0.35.0 EDGE-2: UnitDualQuaternion::sclerp of poses {angle:.2e} rad apart is NaN: acos(1 + 2^-52) of the relative motion's scalar part");
    println!("call:    UnitDualQuaternion::new_normalize(a).sclerp(&UnitDualQuaternion::new_normalize(b), t)   (f64)");
    println!("input:   a = {}\n         b = {}\n         t = {}", hxs(&a), hxs(&b), hx(t));
    println!("         relative motion a* b: scalar part {} (1 + {:.1e}), |v|^2 = {:.3e} > eps", hx(rel.real.w), rel.real.w - 1.0, rel.real.vector().norm_squared());
    println!("library: {}", hxs(&got));
    println!("correct: a finite unit dual quaternion between a and b (the screw motion a (a* b)^t; a rotation of {angle:.2e} rad)");
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

/// METRIC-1: the angle of the rotation separating a and b (each normalised first), sign-blind.
fn metric1(a: &[f64], b: &[f64]) -> f64 {
    let na = a.iter().map(|x| x * x).sum::<f64>().sqrt();
    let nb = b.iter().map(|x| x * x).sum::<f64>().sqrt();
    let (mut dm, mut dp) = (0.0, 0.0);
    for i in 0..4 {
        let (x, y) = (a[i] / na, b[i] / nb);
        dm += (x - y) * (x - y);
        dp += (x + y) * (x + y);
    }
    let (dm, dp) = (dm.sqrt(), dp.sqrt());
    4.0 * dm.min(dp).atan2(dm.max(dp))
}
