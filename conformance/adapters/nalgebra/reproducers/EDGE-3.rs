//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause EDGE-3.
//!
//! EDGE-3 (spec/SPEC.md 9, eps16): a hemisphere test on a dot of +-0 does not flip (the other
//! hemisphere is ACCEPTABLE, ACC-1 hemisphere_tie), and an exact antipode flips: the interpolation
//! is constant. Two nalgebra calls fail it:
//!  - UnitDualQuaternion::sclerp panics, "DualQuaternion sclerp: ambiguous configuration.", when the
//!    real parts are orthogonal (try_sclerp returns None when |a_r . b_r| <= eps,
//!    src/geometry/dual_quaternion.rs:674-678; sclerp's .expect, :645-650). The panic is documented
//!    ("Panics if the angle between both quaternion is 180 degrees (in which case the interpolation
//!    is not well-defined)"), so the adapter reads it as a refusal (DOMAIN_ERROR); but the
//!    interpolation is defined there (either of the two equally short screws, ACC-1), and a refusal
//!    of a finite, unit input is a wrong status. Maintainers may regard it as by design.
//!  - UnitQuaternion::nlerp has no hemisphere flip (NLERP-1.rs): at an exact antipode its sum
//!    cancels (322 eps at t = 0.5006, NaN at t = 1/2).
//! Upstream: no matching issue found in dimforge/nalgebra (issue #1013 was the panic for equal
//! rotations, fixed by PR #1016).
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example EDGE-3
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{DualQuaternion, Quaternion, UnitDualQuaternion, UnitQuaternion};

fn unit(d: &[f64]) -> UnitDualQuaternion<f64> {
    UnitDualQuaternion::new_normalize(DualQuaternion::from_real_and_dual(
        Quaternion::new(d[3], d[0], d[1], d[2]),
        Quaternion::new(d[7], d[4], d[5], d[6]),
    ))
}

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 EDGE-3: UnitDualQuaternion::sclerp panics on orthogonal real parts (a relative half turn); UnitQuaternion::nlerp cancels at an exact antipode");
    let mut shown = false;
    std::panic::set_hook(Box::new(|_| {})); // the panic is reported below
    // The suite's input (dot exactly 0, binary64).
    let a: Vec<f64> = ["0x1.1d6aa9bccea6p-1", "0x1.8a67ecd160adfp-2", "0x1.518d94bed2d0dp-1", "-0x1.4dc496f454f0ap-2", "0x1.ea95900f242d4p-3", "0x1.0382bd19c4dcfp-4", "-0x1.abd7ee85ab369p-3", "0x1.fbe0c9b18ca1fp-5"].iter().map(|s| hexf(s)).collect();
    let b: Vec<f64> = ["-0x1.8a67ecd160adfp-2", "0x1.1d6aa9bccea6p-1", "0x1.4dc496f454f0ap-2", "0x1.518d94bed2d0dp-1", "0x1.3d5532e8650f7p-4", "-0x1.4c8cd12564fp-7", "-0x1.479b6b72993f2p-1", "0x1.7b116efaed76bp-2"].iter().map(|s| hexf(s)).collect();
    let t = hexf("0x1.0a06ea3fe3eedp-1");
    let dot: f64 = (0..4).map(|i| a[i] * b[i]).sum();
    let (ua, ub) = (unit(&a), unit(&b));
    let result = std::panic::catch_unwind(|| ua.sclerp(&ub, t));
    println!("call:    UnitDualQuaternion::new_normalize(a).sclerp(&UnitDualQuaternion::new_normalize(b), t)   (f64; f32 alike)");
    println!("input:   a = {}\n         b = {}\n         t = {}   (real parts: a . b = {})", hxs(&a), hxs(&b), hx(t), hx(dot));
    match result {
        Ok(r) => println!("library: {:?}", r.dual_quaternion()),
        Err(e) => {
            shown = true;
            let msg = e.downcast_ref::<&str>().map(|s| s.to_string()).or_else(|| e.downcast_ref::<String>().cloned()).unwrap_or_default();
            println!("library: panic: {msg}  <-- DEFECT (a refusal)");
        }
    }
    println!("correct: the screw interpolation a (a* b)^t (no flip at a dot of 0; -b's screw is ACCEPTABLE)");

    // nlerp at an exact antipode (the suite's worst input): cancellation.
    let q = [hexf("0x1.84093368cf5f2p-2"), hexf("-0x1.397fa5980563cp-1"), hexf("-0x1.ae9049868e252p-3"), hexf("-0x1.529337bec0ef3p-1")];
    let t = hexf("0x1.004baae113429p-1");
    let ua = UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[0], q[1], q[2]));
    let ub = UnitQuaternion::from_quaternion(Quaternion::new(-q[3], -q[0], -q[1], -q[2]));
    let r = ua.nlerp(&ub, t);
    let got = [r.i, r.j, r.k, r.w];
    let err = metric1(&got, &[ua.i, ua.j, ua.k, ua.w]) / f64::EPSILON;
    shown |= err > 256.0;
    println!("call:    UnitQuaternion::from_quaternion(a).nlerp(&UnitQuaternion::from_quaternion(-a), t)   (f64)");
    println!("input:   a = {}, b = -a, t = {}", hxs(&q), hx(t));
    println!("library: {} ({err:.3e} eps from a, METRIC-1; loose bar 256 eps)", hxs(&got));
    println!("correct: a (up to sign): b' = -b = a, the interpolation is constant");
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
