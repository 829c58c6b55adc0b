//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause DQ-4.
//!
//! DQ-4 (spec/SPEC.md 8.4, eps16): normalising r + eps d gives r' = r/|r| and d' = d/|r| -
//! ((r.d)/|r|^3) r, so that |r'| = 1 and r'.d' = 0 (a unit dual quaternion; the component of d
//! along r carries no translation). DualQuaternion::normalize (src/geometry/dual_quaternion.rs:
//! 106-113), like UnitDualQuaternion::new_normalize (the Normed impl, :393-416), divides both parts
//! by |r| and leaves r'.d' = (r.d)/|r|^2: the result, which new_normalize wraps as a
//! UnitDualQuaternion, is not a unit dual quaternion.
//! Upstream: no matching issue found in dimforge/nalgebra (gl-matrix fixed the same in PR #327).
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example DQ-4
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{DualQuaternion, Quaternion};

fn main() {
    // EX-DQ-4-b: real = 1, dual = (0, 0, 0, 1): r.d = 1.
    let d = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let dq = DualQuaternion::from_real_and_dual(Quaternion::new(d[3], d[0], d[1], d[2]), Quaternion::new(d[7], d[4], d[5], d[6]));
    let n = dq.normalize();
    let got = [n.real.i, n.real.j, n.real.k, n.real.w, n.dual.i, n.dual.j, n.dual.k, n.dual.w];
    let rd: f64 = (0..4).map(|i| got[i] * got[4 + i]).sum();
    let err = rd.abs() / f64::EPSILON;

    println!("rotorcert reproducer: nalgebra 0.35.0 DQ-4: DualQuaternion::normalize divides by |real| only: real . dual stays {rd} (must be 0), {err:.3e} eps");
    println!("call:    DualQuaternion::from_real_and_dual(real, dual).normalize()   (f64; f32 alike)");
    println!("input:   d [real xyzw, dual xyzw] = {}   (EX-DQ-4-b)", hxs(&d));
    println!("library: {}   (real . dual = {})", hxs(&got), hx(rd));
    println!("correct: [0x0p+0, 0x0p+0, 0x0p+0, 0x1p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]   (d' = d/|r| - (r.d)/|r|^3 r)");
    println!("error:   |real' . dual'| = {err:.3e} eps (DQ-4's defect term; eps = 2^-52; loose bar 256 eps)");
    if err <= 256.0 {
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
