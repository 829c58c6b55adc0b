//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause EDGE-5.
//!
//! EDGE-5 (spec/SPEC.md 9, eps16): a finite nonzero q means the rotation q/|q| at every scale the
//! format holds (NORM-1: no intermediate overflow or underflow; INV-1: q*/|q|^2 for every finite
//! nonzero q). Quaternion::normalize, UnitQuaternion::from_quaternion and
//! UnitDualQuaternion::new_normalize divide by norm() = sqrt(norm_squared()) (src/base/norm.rs:
//! 257-262, unscaled): the squares overflow above ~2^511 (f64) / 2^63 (f32), so every rotation
//! op gives zeros there, and underflow below ~2^-538 / 2^-75 (Inf, NaN). Quaternion::try_inverse
//! ("Inverts this quaternion if it is not zero") refuses every q with |q|^2 < default_epsilon
//! (src/geometry/quaternion.rs:633-638): |q| < 1.5e-8 in f64 and |q| < 3.5e-4 in f32, nonzero
//! quaternions with a perfectly representable inverse.
//! Upstream: no matching issue found in dimforge/nalgebra.
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example EDGE-5
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::Quaternion;

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 EDGE-5: normalize over/underflows outside ~2^-538..2^511 (f64); try_inverse refuses |q|^2 < eps (|q| < 3.5e-4 in f32)");
    let mut shown = false;

    // EX-NORM-1-f: components 2^1023.
    let q = [hexf("0x1p+1023"); 4];
    let n = Quaternion::new(q[3], q[0], q[1], q[2]).normalize();
    let got = [n.i, n.j, n.k, n.w];
    let bad = got.iter().any(|&x| (x - 0.5).abs() > 1e-15);
    shown |= bad;
    println!("call:    Quaternion::new(w, x, y, z).normalize()   (f64, EX-NORM-1-f)");
    println!("input:   q [x, y, z, w] = {}", hxs(&q));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: [0x1p-1, 0x1p-1, 0x1p-1, 0x1p-1]");

    // EX-NORM-1-h: (1.5 2^-999, 0, 0, 2^-998).
    let q = [hexf("0x1.8p-999"), 0.0, 0.0, hexf("0x1p-998")];
    let n = Quaternion::new(q[3], q[0], q[1], q[2]).normalize();
    let got = [n.i, n.j, n.k, n.w];
    let bad = got.iter().any(|x| !x.is_finite());
    shown |= bad;
    println!("call:    Quaternion::new(w, x, y, z).normalize()   (f64, EX-NORM-1-h)");
    println!("input:   q [x, y, z, w] = {}", hxs(&q));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: [0x1.3333333333333p-1, 0x0p+0, 0x0p+0, 0x1.999999999999ap-1] (0.6, 0, 0, 0.8)");

    // try_inverse of a small (f32: ordinary) quaternion.
    let q = [0.0, 0.0, 0.0, hexf("0x1p-13")];
    let inv = Quaternion::new(q[3] as f32, 0.0, 0.0, 0.0).try_inverse();
    let bad = inv.is_none();
    shown |= bad;
    println!("call:    Quaternion::new(w, x, y, z).try_inverse()   (f32)");
    println!("input:   q [x, y, z, w] = {}   (|q|^2 = 2^-26 < f32::EPSILON = 2^-23)", hxs(&q));
    println!("library: {:?}{}", inv, if bad { "  <-- DEFECT (refused)" } else { "" });
    println!("correct: [0x0p+0, 0x0p+0, 0x0p+0, 0x1p+13] (q*/|q|^2 = 1/q)");
    let q = [hexf("-0x1.fce3c6dc657fep-901"), hexf("-0x1.8a9b59ecd5d55p-905"), hexf("-0x1.a12056e880dafp-900"), hexf("-0x1.c423be70e784fp-903")];
    let inv = Quaternion::new(q[3], q[0], q[1], q[2]).try_inverse();
    let bad = inv.is_none();
    shown |= bad;
    println!("call:    Quaternion::new(w, x, y, z).try_inverse()   (f64, the suite's input at scale 2^-900)");
    println!("input:   q [x, y, z, w] = {}", hxs(&q));
    println!("library: {:?}{}", inv, if bad { "  <-- DEFECT (refused)" } else { "" });
    println!("correct: q*/|q|^2, components ~2^+900 (finite)");

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
