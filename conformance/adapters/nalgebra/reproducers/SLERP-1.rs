//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clauses SLERP-1
//! and SLERP-2 (the same call).
//!
//! SLERP-1 (spec/SPEC.md 8.2, eps16, METRIC-1 and METRIC-6): slerp(a, b, t) = (sin((1-t) W) a +
//! sin(t W) b') / sin W is unit and accurate to a few eps at every angle; it SHOULD NOT take W
//! from acos(a.b). UnitQuaternion::slerp calls Unit<Vector4>::try_slerp (src/base/interpolation.rs:
//! 108-128), which returns `self` when c = a.b rounds to 1 or above (:111-113) and otherwise takes
//! hang = acos(c) and s_hang = sqrt(1 - c^2): for nearby rotations c rounds to 1 below ~3e-8 rad
//! (binary64) / ~5e-4 rad (binary32), so the result is a for every t, and just above that
//! 1 - c^2 keeps only a few bits (its absolute error ~eps is a relative error eps / W^2), and so
//! do the weights sin((1-t) hang) / s_hang, sin(t hang) / s_hang: the result is off the arc and
//! not unit (1.6e8 eps at W ~ 3e-8 in binary64, 5.6e3 eps at W ~ 6e-4 in binary32).
//! Upstream: no matching issue found in dimforge/nalgebra.
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example SLERP-1
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{Quaternion, UnitQuaternion};

/// slerp with W = 2 atan2(|a - b'|, |a + b'|) (METRIC-1's well-conditioned angle): a few eps.
fn slerp_ref(a: &[f64], b: &[f64], t: f64) -> Vec<f64> {
    let dot: f64 = (0..4).map(|i| a[i] * b[i]).sum();
    let b: Vec<f64> = b.iter().map(|x| if dot < 0.0 { -x } else { *x }).collect();
    let dm = (0..4).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
    let dp = (0..4).map(|i| (a[i] + b[i]).powi(2)).sum::<f64>().sqrt();
    let w = 2.0 * dm.atan2(dp);
    let (ca, cb) = (((1.0 - t) * w).sin() / w.sin(), (t * w).sin() / w.sin());
    (0..4).map(|i| ca * a[i] + cb * b[i]).collect()
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 SLERP-1: UnitQuaternion::slerp of nearby rotations returns a when a.b rounds to 1, and takes sqrt(1 - c^2) of c = a.b just above: off the arc, not unit");
    let mut shown = false;
    // binary64: the suite's worst input (near-identical pair, distance 2^-25).
    let a = [hexf("0x1.e07c3105de9dap-1"), hexf("0x1.0d3849c66b6c2p-5"), hexf("0x1.2e6ed947826a3p-3"), hexf("0x1.3dfbade9a4e47p-2")];
    let b = [hexf("0x1.e07c30dc748eap-1"), hexf("0x1.0d3850534fa1cp-5"), hexf("0x1.2e6ed8a5fba5p-3"), hexf("0x1.3dfbaef42e9edp-2")];
    let t = hexf("0x1.ae7bddfe139e5p-1");
    let ua = UnitQuaternion::from_quaternion(Quaternion::new(a[3], a[0], a[1], a[2]));
    let ub = UnitQuaternion::from_quaternion(Quaternion::new(b[3], b[0], b[1], b[2]));
    let r = ua.slerp(&ub, t);
    let got = [r.i, r.j, r.k, r.w];
    let want = slerp_ref(&[ua.i, ua.j, ua.k, ua.w], &[ub.i, ub.j, ub.k, ub.w], t);
    let eps = f64::EPSILON;
    let (d, n) = (metric1(&got, &want) / eps, (norm(&got) - 1.0).abs() / eps);
    shown |= d.max(n) > 256.0;
    println!("call:    UnitQuaternion::from_quaternion(a).slerp(&UnitQuaternion::from_quaternion(b), t)   (f64)");
    println!("input:   a = {}\n         b = {}\n         t = {}", hxs(&a), hxs(&b), hx(t));
    println!("library: {} {}", hxs(&got), dec(&got));
    println!("correct: {} {}   (W from atan2 of |a - b|, |a + b|, in binary64: a few eps)", hxs(&want), dec(&want));
    println!("error:   {d:.3e} eps (METRIC-1), norm defect {n:.3e} eps (METRIC-6); eps = 2^-52, loose bar 256 eps");

    // binary32: the suite's worst input at 64 cases per family.
    let a = [hexf("-0x1.79a57p-3"), hexf("-0x1.ff2deap-3"), hexf("0x1.4f6286p-1"), hexf("0x1.60b9f6p-1")];
    let b = [hexf("-0x1.79c1ccp-3"), hexf("-0x1.ff447ep-3"), hexf("0x1.4f3a92p-1"), hexf("0x1.60dcp-1")];
    let t = hexf("0x1.a67e3ap-1");
    let ua = UnitQuaternion::from_quaternion(Quaternion::new(a[3] as f32, a[0] as f32, a[1] as f32, a[2] as f32));
    let ub = UnitQuaternion::from_quaternion(Quaternion::new(b[3] as f32, b[0] as f32, b[1] as f32, b[2] as f32));
    let r = ua.slerp(&ub, t as f32);
    let got = [r.i as f64, r.j as f64, r.k as f64, r.w as f64];
    let want = slerp_ref(&[ua.i as f64, ua.j as f64, ua.k as f64, ua.w as f64], &[ub.i as f64, ub.j as f64, ub.k as f64, ub.w as f64], t);
    let eps = f32::EPSILON as f64;
    let (d, n) = (metric1(&got, &want) / eps, (norm(&got) - 1.0).abs() / eps);
    shown |= d.max(n) > 256.0;
    println!("call:    the same with f32");
    println!("input:   a = {}\n         b = {}\n         t = {}", hxs(&a), hxs(&b), hx(t));
    println!("library: {} {}", hxs(&got), dec(&got));
    println!("correct: {} {}   (computed in binary64 from the binary32 unit inputs)", hxs(&want), dec(&want));
    println!("error:   {d:.3e} eps (METRIC-1), norm defect {n:.3e} eps (METRIC-6); eps = 2^-23, loose bar 256 eps");

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
