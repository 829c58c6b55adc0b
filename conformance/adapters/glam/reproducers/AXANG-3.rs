//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause AXANG-3.
//!
//! AXANG-3 (spec/SPEC.md 6, level Extended, tolerance eps16, absolute error in radians): the angle
//! alone, theta = 2 atan2(|v|, w) in [0, 2 pi]; an angle of the same rotation about another axis
//! (2 pi - theta, signed) is ACCEPTABLE (ACC-1 angle_range: |rho(angle) - rho(theta)|, rho the
//! angle in [0, pi]). glam has no angle-only query: its angle is DQuat::to_axis_angle().1
//! (src/f64/dquat.rs:404-417), which returns (DVec3::X, 0.0) whenever |v| < EPSILON with
//! `const EPSILON: f64 = 1.0e-8;` (:407, :415), the binary32 template's threshold that binary64
//! inherits: the angle of every rotation within 2e-8 rad of a full turn reads 0 (and within 2e-8
//! rad of the identity, 0 instead of 2|v|), off by 2 pi - theta under any angle range. The
//! AXANG-1 defect (AXANG-1.rs), met by the angle alone.
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example AXANG-3
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::DQuat;

fn main() {
    // The suite's worst input (near a full turn: 2 pi - 1e-9 .. 1e-1): |v| = 5.0e-10, w = -1.
    let q = [hexf("0x1.193445dad6368p-38"), hexf("0x1.1415859630bd8p-31"), hexf("-0x1.e0019d641e355p-36"), hexf("-0x1p+0")];
    let angle = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_axis_angle().1;

    // Closed form in binary64: |v| and atan2 are well-conditioned here (a few ulp).
    let nv = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    let theta = 2.0 * nv.atan2(q[3]);
    let rho = |x: f64| 2.0 * (x / 2.0).sin().abs().atan2((x / 2.0).cos().abs());
    let eps = f64::EPSILON;
    let err = (angle - theta).abs() / eps;
    let err_conv = (rho(angle) - rho(theta)).abs() / eps;

    println!("rotorcert reproducer: glam 0.34.3 AXANG-3: DQuat::to_axis_angle().1 is 0 for every rotation within 2e-8 rad of a full turn (|v| < 1e-8), {err_conv:.3e} eps under any angle range");
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_axis_angle().1");
    println!("input:   q [x, y, z, w] = {}   (|v| = {nv:.3e})", hxs(&q));
    println!("library: angle = {}", hx(angle));
    println!("correct: angle = 2 atan2(|v|, w) = {} ({theta:.12})", hx(theta));
    println!("error:   {err:.3e} eps (absolute, AXANG-3); {err_conv:.3e} eps under any angle range, |rho(angle) - rho(theta)| (eps = 2^-52; loose bar 256 eps)");
    if err_conv <= 256.0 {
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
