//! Hard inputs of the warps and the frame, each with the behaviour it requires, one test per
//! case (run one by name, e.g. `cargo test --test all warp::hard_cases::case_04`):
//!
//! - exact values at the centre of the square: the concentric map (Shirley and Chiu 1997) sends
//!   (½, ½) to (0, 0), so the cosine hemisphere (Malley's method) gives +z with pdf 1/π (1); and
//!   finite, in-domain results on the square's boundary (2, 14);
//! - the precision cliffs of the textbook forms: the sphere's radius 2√(u₀(1 − u₀)) = 2e-4 at
//!   u₀ = 1e-8, where √(1 − z²) in f32 gives 0 (3); cones of h = 1 − cos θmax = 1e-7 and of
//!   sin²θmax = 1e-8, with h = s²/(1 + √(1 − s²)) (4–6); a Phong lobe of exponent 10⁶, where the
//!   naive cos α = u₀^{1/(n+1)} collapses onto a few directions, and of exponent 0, which is the
//!   uniform hemisphere (7, 8);
//! - barycentrics of the low-distortion triangle map (Heitz 2019) that stay non-negative on the
//!   diagonal u₀ = u₁ (9);
//! - Arvo's (1995) spherical triangle at 3e-7 sr, where f32 meets the 1e-4 pdf bound only with
//!   Van Oosterom and Strackee's (1983) solid angle on raw edge vectors (the angle sum is 47 %
//!   off) (10), and degenerate triangles (11); Ureña et al.'s (2013) spherical rectangle seen
//!   edge-on (17);
//! - the orthonormal frame of Duff et al. (2017) at n_z = −0.9999999, where Frisvad's 2012 form
//!   breaks down, and at ±z (12);
//! - NaN inputs, alone and mixed with other bad values across the lanes of a packet: the packet
//!   form equals the scalar form bit for bit, and NaN outputs are the canonical quiet NaN (15,
//!   15b);
//! - and the bad-input behaviour that the rustdoc of `mcsample::warp` and `mcsample::frame`
//!   promises (`doc_*`): clamped u, cone h and Phong n, pdfs of 0 outside the support, degenerate
//!   polygons.
//!
//! Case numbers are stable names across the layers: the MIS and roulette cases (13, 18, 25) are
//! in `estimate::hard_cases`, the lights' and BSDFs' (16, 20–24, 26) in `scene::hard_cases`, and
//! 19 (the generators' u < 1) in `seq::generators`. A case may check many inputs: it collects
//! every sub-failure and reports them together.

use std::rc::Rc;

use crate::common::hard_case;
use crate::common::*;
use glam::{Vec2, Vec3};
use mcsample::frame::Frame;
use mcsample::verify::registry::{self, Kind, NanPolicy, Sampler};
use mcsample::verify::{Bits, LaneMismatch, Scalar, check_lanes, check_lanes16};
use mcsample::warp::{self, ONE_MINUS_EPS};
use mcsample::x8::{F32x8, Vec2x8, Vec3x8};
use mcsample::x16::Vec2x16;

/// The scalar components of a result, in order (a direction and its pdf: x, y, z, pdf).
type Out = Vec<f32>;
type Check = Box<dyn Fn(&[f32]) -> Result<(), String>>;
/// `check_lanes` of a packet form against its scalar form, on the given inputs.
type Lanes<S> = Box<dyn Fn(&[S]) -> Result<usize, Box<LaneMismatch>>>;

/// The components of `v`, bit for bit (NaN payloads included).
fn flat(v: impl Bits) -> Out {
    v.bits().into_iter().map(f32::from_bits).collect()
}
fn s3(v: Vec3) -> Vec3x8 {
    Vec3x8::splat(v)
}
fn s1(x: f32) -> F32x8 {
    F32x8::splat(x)
}
fn dv3(v: Vec3) -> D3 {
    [v.x as f64, v.y as f64, v.z as f64]
}

/// A `check_lanes` result as a case's sub-result.
fn same_lanes(what: &str, r: Result<usize, Box<LaneMismatch>>) -> Result<(), String> {
    r.map(drop).map_err(|e| format!("{what}: {e}"))
}

/// Every NaN output is the canonical quiet NaN, bits 0x7fc0_0000 (crate docs, "Bad input").
fn canonical(what: &str, v: &[f32]) -> Result<(), String> {
    match v.iter().find(|x| x.is_nan() && x.to_bits() != 0x7fc0_0000) {
        None => Ok(()),
        Some(x) => Err(format!(
            "{what}: non-canonical NaN {:#010x} in {v:?}",
            x.to_bits()
        )),
    }
}

fn finite(what: &str, v: &[f32]) -> Result<(), String> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(format!("{what}: non-finite output {v:?}"))
    }
}

fn unit(what: &str, v: &[f32]) -> Result<(), String> {
    let l = dv3(Vec3::new(v[0], v[1], v[2]));
    let l = norm(l);
    if (l - 1.0).abs() <= 1e-6 {
        Ok(())
    } else {
        Err(format!("{what}: |w| = {l} for {v:?}"))
    }
}

// ---------------------------------------------------------------------------------------------
// The warps: the registry's, each with its scalar face, its packet face and its domain.

struct Warp {
    name: String,
    /// The scalar form, its result flattened: the point (x, y, z) and the pdf.
    s: Box<dyn Fn(Vec2) -> Out>,
    /// The packet form against the scalar form.
    lanes: Lanes<Vec2>,
    domain: Check,
    /// How many coordinates of the point NaN in u makes NaN (the planar ones pad z = 0).
    nan_coords: usize,
    /// The documented fixed output of a spherical polygon sampler at NaN u.
    fixed: Option<Vec3>,
}

/// A sampler of the registry as a hard case.
fn warp_case(s: Sampler) -> Warp {
    Warp {
        name: s.name(),
        s: Box::new(move |u| flat(s.sample(u))),
        lanes: Box::new(move |us| {
            check_lanes(us, |u: Vec2x8| s.sample(u), |u: Vec2| s.sample(u))?;
            check_lanes16(us, |u: Vec2x16| s.sample(u), |u: Vec2| s.sample(u))
        }),
        domain: domain(s),
        nan_coords: s.nan_coords(),
        fixed: s.dropped_at(),
    }
}

/// The domain of a sampler's point, checked independently of the registry where the family has
/// a check of its own here; the registry's domain otherwise.
fn domain(s: Sampler) -> Check {
    match s {
        Sampler::ConcentricDisk(_) | Sampler::PolarDisk(_) => disk_domain(),
        Sampler::UniformHemisphere(_) | Sampler::CosineHemisphere(_) | Sampler::PhongLobe(_) => {
            dir_domain(0.0)
        }
        Sampler::UniformSphere(_) => dir_domain(-1.0),
        Sampler::UniformCone(c) => dir_domain(1.0 - c.h as f64 - 1e-6),
        Sampler::UniformTriangle(_) => Box::new(|b| {
            finite("uniform_triangle", b)?;
            let sum = b[0] as f64 + b[1] as f64 + b[2] as f64;
            if b.iter().all(|&x| x >= 0.0) && (sum - 1.0).abs() <= 1e-6 {
                Ok(())
            } else {
                Err(format!("uniform_triangle: b = {b:?}, sum {sum}"))
            }
        }),
        Sampler::Tent(_) => Box::new(|x| {
            if (-1.0..=1.0).contains(&x[0]) && (-1.0..=1.0).contains(&x[1]) && x[2] == 0.0 {
                Ok(())
            } else {
                Err(format!("tent: x = {x:?}"))
            }
        }),
        Sampler::SphericalTriangle(t) => sph_tri_domain(t.v[0], t.v[1], t.v[2]),
        Sampler::BilinearTriangle(t) => sph_tri_domain(t.v[0], t.v[1], t.v[2]),
        Sampler::SphericalRectangle(r) => sph_rect_domain(r.v[0], r.v[1], r.v[2]),
        Sampler::BilinearRectangle(r) => sph_rect_domain(r.v[0], r.v[1], r.v[2]),
        _ => Box::new(move |x| {
            let p = Vec3::new(x[0], x[1], x[2]);
            check(s.in_domain(p), || format!("{}: {x:?} outside", s.name()))
        }),
    }
}

fn disk_domain() -> Check {
    Box::new(|v| {
        finite("disk", v)?;
        let r = (v[0] as f64).hypot(v[1] as f64);
        if r <= 1.0 + 1e-6 {
            Ok(())
        } else {
            Err(format!("disk: |p| = {r}"))
        }
    })
}

fn dir_domain(z_min: f64) -> Check {
    Box::new(move |v| {
        finite("direction", v)?;
        unit("direction", v)?;
        if v[2] as f64 >= z_min {
            Ok(())
        } else {
            Err(format!("direction: z = {:e} < {z_min:e}", v[2]))
        }
    })
}

/// A spherical-triangle sample: unit, finite, pdf > 0 and inside the triangle within 1e-5 rad.
fn sph_tri_domain(a: Vec3, b: Vec3, c: Vec3) -> Check {
    Box::new(move |v| {
        finite("spherical_triangle", v)?;
        unit("spherical_triangle", v)?;
        if v[3].is_nan() || v[3] <= 0.0 {
            return Err(format!("spherical_triangle: pdf {} ≤ 0", v[3]));
        }
        let out =
            spherical_triangle_outside(dv3(Vec3::new(v[0], v[1], v[2])), dv3(a), dv3(b), dv3(c));
        if out <= 1e-5 {
            Ok(())
        } else {
            Err(format!(
                "spherical_triangle: {out:e} rad outside, w = {v:?}"
            ))
        }
    })
}

/// A spherical-rectangle sample: a finite point on the rectangle (s, t ∈ [0, 1] within 1e-5, in
/// the plane within 1e-5 of its distance) and pdf > 0.
fn sph_rect_domain(corner: Vec3, ex: Vec3, ey: Vec3) -> Check {
    Box::new(move |v| {
        finite("spherical_rectangle", v)?;
        if v[3].is_nan() || v[3] <= 0.0 {
            return Err(format!("spherical_rectangle: pdf {} ≤ 0", v[3]));
        }
        let p = dv3(Vec3::new(v[0], v[1], v[2]));
        let st = rect_coords(p, dv3(corner), dv3(ex), dv3(ey));
        // 1e-5, or what the f32 sum corner + s·ex + t·ey rounds to at the light's distance,
        // relative to its size (a 1e-3-wide light at distance 1 rounds to 1e-4 of itself).
        let size = ex.length().min(ey.length()) as f64;
        let tol = 1e-5f64.max(
            4.0 * f32::EPSILON as f64 * (corner.length() + ex.length() + ey.length()) as f64 / size,
        );
        if st[0] < -tol || st[0] > 1.0 + tol || st[1] < -tol || st[1] > 1.0 + tol {
            return Err(format!(
                "spherical_rectangle: (s, t) = {st:?} for p = {v:?}"
            ));
        }
        if st[2].abs() > 1e-5 * norm(p) {
            return Err(format!("spherical_rectangle: {:e} off the plane", st[2]));
        }
        Ok(())
    })
}

// The test geometry, in f32.
const TRI_LARGE: [[f32; 3]; 3] = [
    [1.0, 0.0, 0.1],
    [-0.5, 0.866_025_4, 0.1],
    [-0.5, -0.866_025_4, 0.1],
];
const RECT_BIG: [[f32; 3]; 3] = [[-1.0, -0.5, 0.8], [2.0, 0.0, 0.0], [0.0, 1.5, 0.0]];

fn f32s(v: (D3, D3, D3)) -> [[f32; 3]; 3] {
    [f3(v.0), f3(v.1), f3(v.2)]
}
/// A triangle just above the spherical-sampling threshold: Ω ≈ 3·SPHERICAL_TRIANGLE_MIN_SR.
fn tri_small() -> [[f32; 3]; 3] {
    let omega = 3.0 * warp::SPHERICAL_TRIANGLE_MIN_SR as f64;
    let dir = normalize([0.3, -0.2, 1.0]);
    f32s(equilateral(dir, [0.6, -0.2, 1.0], side_for(omega, 1.0)))
}
/// A triangle sampled by area: Ω ≈ 0.1·SPHERICAL_TRIANGLE_MIN_SR.
fn tri_tiny() -> [[f32; 3]; 3] {
    let omega = 0.1 * warp::SPHERICAL_TRIANGLE_MIN_SR as f64;
    let dir = normalize([0.3, -0.2, 1.0]);
    f32s(equilateral(dir, [0.6, -0.2, 1.0], side_for(omega, 1.0)))
}
/// A rectangle just above the spherical-sampling threshold: Ω ≈ 1.5·SPHERICAL_RECTANGLE_MIN_SR.
fn rect_small() -> [[f32; 3]; 3] {
    let s = (1.5 * warp::SPHERICAL_RECTANGLE_MIN_SR as f64).sqrt();
    f32s(centred_rectangle(
        normalize([0.3, -0.2, 1.0]),
        [0.6, -0.2, 1.0],
        s * 1.1,
        s,
        0.4,
    ))
}
/// A rectangle sampled by area: Ω ≈ 2.4e-7 sr.
fn rect_tiny() -> [[f32; 3]; 3] {
    [[0.3, 0.2, 2.0], [0.001, 0.0, 0.0], [0.0, 0.001, 0.0]]
}

fn v(a: [f32; 3]) -> Vec3 {
    Vec3::from_array(a)
}

/// The registry's warps and spherical polygons, with the ends of the parameter ranges (the whole
/// sphere and a pinpoint cone, the uniform hemisphere and a needle lobe) and the polygons at the
/// spherical-sampling thresholds.
fn samplers() -> Vec<Sampler> {
    let mut all: Vec<Sampler> = registry::registry()
        .into_iter()
        .filter(|s| matches!(s.kind(), Kind::Warp(_) | Kind::Polygon(_)))
        .collect();
    all.extend([2.0f32, 1e-7].map(|h| Sampler::from(warp::UniformCone { h })));
    all.extend([0.0f32, 1e6].map(|n| Sampler::from(warp::PhongLobe { n })));
    for t in [TRI_LARGE, tri_small(), tri_tiny()] {
        all.push(warp::SolidAngleTriangle { v: t.map(v) }.into());
    }
    for r in [RECT_BIG, rect_small(), rect_tiny()] {
        all.push(warp::SolidAngleRectangle { v: r.map(v) }.into());
    }
    all
}

fn warps() -> Vec<Warp> {
    samplers().into_iter().map(warp_case).collect()
}

/// Functions of one f32 (pdfs, inverses, helpers, warps in their parameter) for the NaN case.
struct Fun {
    name: String,
    /// The scalar form, its result flattened.
    s: Box<dyn Fn(f32) -> Out>,
    /// The packet form against the scalar form.
    lanes: Lanes<f32>,
    /// What the documentation promises at NaN input.
    at_nan: Check,
}

fn fun_case<T: Scalar + 'static>(
    name: impl Into<String>,
    scalar: impl Fn(f32) -> T + 'static,
    packet: impl Fn(F32x8) -> T::X8 + 'static,
    at_nan: Check,
) -> Fun {
    let scalar = Rc::new(scalar);
    let s = Rc::clone(&scalar);
    Fun {
        name: name.into(),
        s: Box::new(move |x| flat(s(x))),
        lanes: Box::new(move |xs| check_lanes(xs, &packet, &*scalar)),
        at_nan,
    }
}

fn is_zero(what: impl Into<String>) -> Check {
    let what = what.into();
    Box::new(move |v| {
        if v.iter().all(|&x| x == 0.0) {
            Ok(())
        } else {
            Err(format!("{what}: pdf at NaN is {v:?}, documented 0"))
        }
    })
}
fn last_is_zero(what: impl Into<String>) -> Check {
    let what = what.into();
    Box::new(move |v| {
        if v[v.len() - 1] == 0.0 {
            Ok(())
        } else {
            Err(format!("{what}: pdf at NaN is {v:?}, documented 0"))
        }
    })
}
fn all_nan(what: impl Into<String>) -> Check {
    let what = what.into();
    Box::new(move |v| {
        if v.iter().all(|x| x.is_nan()) {
            Ok(())
        } else {
            Err(format!("{what}: NaN in gives {v:?}, documented NaN"))
        }
    })
}
fn any() -> Check {
    Box::new(|_| Ok(()))
}

/// A point built from one lane: its scalar and packet forms, and the coordinates that NaN in
/// the lane makes NaN.
type Shape = (fn(f32) -> Vec3, fn(F32x8) -> Vec3x8, &'static [usize]);

/// Every hard-case sampler's pdf and inverse at points built from one lane x: directions
/// (x, x, x) and (0, 0, x), barycentrics (x, x, 1 − 2x) and (x, 0.2, 0.8 − x) for the pdf;
/// (x, x, x) and the planar (x, x, 0) for the inverse. At NaN, the pdf is 0 where a coordinate
/// it reads is NaN, and the inverse of a sampler whose policy is NaN out is NaN.
fn sampler_funs() -> Vec<Fun> {
    let pdf_shapes: [(&str, Shape); 4] = [
        (
            "(x, x, x)",
            (|x| Vec3::splat(x), |x| Vec3x8::new(x, x, x), &[0, 1, 2]),
        ),
        (
            "(0, 0, x)",
            (
                |x| Vec3::new(0.0, 0.0, x),
                |x| Vec3x8::new(s1(0.0), s1(0.0), x),
                &[2],
            ),
        ),
        (
            "(x, x, 1 − 2x)",
            (
                |x| Vec3::new(x, x, 1.0 - x - x),
                |x| Vec3x8::new(x, x, s1(1.0) - x - x),
                &[0, 1, 2],
            ),
        ),
        (
            "(x, 0.2, 0.8 − x)",
            (
                |x| Vec3::new(x, 0.2, 0.8 - x),
                |x| Vec3x8::new(x, s1(0.2), s1(0.8) - x),
                &[0, 2],
            ),
        ),
    ];
    let inverse_shapes: [(&str, Shape); 2] = [
        pdf_shapes[0],
        (
            "(x, x, 0)",
            (
                |x| Vec3::new(x, x, 0.0),
                |x| Vec3x8::new(x, x, s1(0.0)),
                &[0, 1],
            ),
        ),
    ];
    let reads_nan = |reads: &[usize], nan: &[usize]| reads.iter().any(|k| nan.contains(k));
    let mut funs = vec![];
    for s in samplers() {
        for (label, (p, p8, nan)) in pdf_shapes {
            let name = format!("{} pdf{label}", s.name());
            let at_nan = if reads_nan(s.pdf_reads(), nan) {
                is_zero(&name)
            } else {
                any()
            };
            funs.push(fun_case(
                &name,
                move |x| s.pdf(p(x)),
                move |x| s.pdf(p8(x)),
                at_nan,
            ));
        }
        for (label, (p, p8, nan)) in inverse_shapes {
            let name = format!("{} inverse{label}", s.name());
            let nan_out = s.nan_policy() == NanPolicy::NanOut;
            let at_nan = if nan_out && reads_nan(s.inverse_reads(), nan) {
                all_nan(&name)
            } else {
                any()
            };
            funs.push(fun_case(
                &name,
                move |x| s.inverse(p(x)),
                move |x| s.inverse(p8(x)),
                at_nan,
            ));
        }
    }
    funs
}

fn funs() -> Vec<Fun> {
    let t = TRI_LARGE.map(v);
    let r = RECT_BIG.map(v);
    let wn = |x: f32| Vec3::new(x, x, x);
    let wn8 = |x: F32x8| Vec3x8::new(x, x, x);
    let zd = |x: f32| Vec3::new(0.0, 0.0, x);
    let zd8 = |x: F32x8| Vec3x8::new(s1(0.0), s1(0.0), x);
    let mut funs = sampler_funs();
    funs.extend([
        fun_case("tent", warp::tent, warp::tent, all_nan("tent")),
        fun_case(
            "uniform_cone_pdf(h)",
            |x| warp::uniform_cone_pdf(Vec3::Z, x),
            |x| warp::uniform_cone_pdf(Vec3x8::splat(Vec3::Z), x),
            is_zero("uniform_cone_pdf"),
        ),
        fun_case(
            "phong_lobe_pdf(0.5, n)",
            move |x| warp::phong_lobe_pdf(zd(0.5), x),
            move |x| warp::phong_lobe_pdf(zd8(s1(0.5)), x),
            is_zero("phong_lobe_pdf(cos, NaN)"),
        ),
        fun_case(
            "tent_pdf",
            warp::tent_pdf,
            warp::tent_pdf,
            is_zero("tent_pdf"),
        ),
        fun_case(
            "tent_inverse",
            warp::tent_inverse,
            warp::tent_inverse,
            any(),
        ),
        fun_case(
            "spherical_triangle_pdf(vertex a)",
            move |x| warp::spherical_triangle_pdf(Vec3::Z, wn(x), t[1], t[2]),
            move |x| warp::spherical_triangle_pdf(s3(Vec3::Z), wn8(x), s3(t[1]), s3(t[2])),
            is_zero("spherical_triangle_pdf"),
        ),
        fun_case(
            "spherical_triangle(vertex c)",
            move |x| warp::spherical_triangle(Vec2::splat(0.3), t[0], t[1], wn(x)),
            move |x| {
                warp::spherical_triangle(
                    Vec2x8::splat(Vec2::splat(0.3)),
                    s3(t[0]),
                    s3(t[1]),
                    wn8(x),
                )
            },
            last_is_zero("spherical_triangle with a NaN vertex"),
        ),
        fun_case(
            "spherical_rectangle(corner)",
            move |x| warp::spherical_rectangle(Vec2::splat(0.3), wn(x), r[1], r[2]),
            move |x| {
                warp::spherical_rectangle(
                    Vec2x8::splat(Vec2::splat(0.3)),
                    wn8(x),
                    s3(r[1]),
                    s3(r[2]),
                )
            },
            last_is_zero("spherical_rectangle with a NaN corner"),
        ),
        fun_case(
            "cone_h_from_sin2",
            warp::cone_h_from_sin2,
            warp::cone_h_from_sin2,
            all_nan("cone_h_from_sin2"),
        ),
        fun_case(
            "cone_h_from_cos",
            warp::cone_h_from_cos,
            warp::cone_h_from_cos,
            any(),
        ),
        fun_case(
            "uniform_cone(u, h)",
            |x| warp::uniform_cone(Vec2::splat(0.3), x),
            |x| warp::uniform_cone(Vec2x8::splat(Vec2::splat(0.3)), x),
            any(),
        ),
        fun_case(
            "phong_lobe(u, n)",
            |x| warp::phong_lobe(Vec2::splat(0.3), x),
            |x| warp::phong_lobe(Vec2x8::splat(Vec2::splat(0.3)), x),
            any(),
        ),
        fun_case(
            "uniform_cone_inverse(w, h)",
            |x| warp::uniform_cone_inverse(Vec3::new(0.1, 0.2, 0.97), x),
            |x| warp::uniform_cone_inverse(s3(Vec3::new(0.1, 0.2, 0.97)), x),
            any(),
        ),
        fun_case(
            "phong_lobe_inverse(w, n)",
            |x| warp::phong_lobe_inverse(Vec3::new(0.1, 0.2, 0.97), x),
            |x| warp::phong_lobe_inverse(s3(Vec3::new(0.1, 0.2, 0.97)), x),
            any(),
        ),
        fun_case(
            "Frame::from_normal + to_world + to_local",
            |x| {
                let f = Frame::from_normal(Vec3::new(x, 0.6, 0.8));
                let v = Vec3::new(0.1, 0.2, 0.3);
                (f.t, f.b, (f.to_world(v), f.to_local(v)))
            },
            |x| {
                let f = mcsample::frame::Frame::from_normal(Vec3x8::new(x, s1(0.6), s1(0.8)));
                let v = s3(Vec3::new(0.1, 0.2, 0.3));
                (f.t, f.b, (f.to_world(v), f.to_local(v)))
            },
            // "NaN components give NaN axes."
            Box::new(|o| {
                let t_nan = o[0..3].iter().any(|x| x.is_nan());
                let b_nan = o[3..6].iter().any(|x| x.is_nan());
                check(t_nan && b_nan, || {
                    format!("Frame at a NaN normal: t, b = {:?}", &o[0..6])
                })
            }),
        ),
    ]);
    funs
}

// ---------------------------------------------------------------------------------------------
// Helpers for individual cases

fn ulp(x: f32) -> f64 {
    let x = x.abs();
    (f32::from_bits(x.to_bits() + 1) - x) as f64
}

/// The bad u components of the input contract.
const BAD: [f32; 10] = [
    -1.0,
    f32::INFINITY,
    f32::NEG_INFINITY,
    1.0,
    1e30,
    f32::MAX,
    -1e-45,
    -0.0,
    f32::MIN,
    1.5,
];

fn clamp01(x: f32) -> f32 {
    x.clamp(0.0, 1.0)
}

/// Degenerate triangles: coincident or collinear vertices, the shading point in the plane (inside
/// the triangle, or not), a vertex at the shading point, non-finite vertices.
fn degenerate_triangles() -> Vec<(&'static str, Vec3, Vec3, Vec3)> {
    let (p, q, s) = (
        Vec3::new(0.3, 0.1, 1.0),
        Vec3::new(-0.2, 0.4, 0.9),
        Vec3::new(0.1, -0.5, 1.1),
    );
    vec![
        ("a = b", p, p, s),
        ("a = b = c", p, p, p),
        ("collinear", p, p * 2.0, p * 3.5),
        ("collinear offset", p, p + (q - p) * 0.5, q),
        (
            "in the plane z = 0, shading point inside",
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(-1.0, -1.0, 0.0),
        ),
        (
            "in the plane z = 0, shading point outside",
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
        ),
        ("plane through the origin", p, q, p * 0.5 - q * 2.0),
        ("vertex at the origin", Vec3::ZERO, q, s),
        ("zero triangle", Vec3::ZERO, Vec3::ZERO, Vec3::ZERO),
        ("infinite vertex", Vec3::new(f32::INFINITY, 0.0, 1.0), q, s),
        ("NaN vertex", Vec3::new(f32::NAN, 0.0, 1.0), q, s),
        // Vertices at f32::MAX are no longer here: their edges overflow f32, but the set-up
        // scales the vertices by a power of two first, and such a triangle is a light
        // (`warp::polygon_regressions` checks its solid angle).
    ]
}

/// Rectangles seen edge-on: the shading point in the plane, beside the rectangle and inside it.
fn edge_on_corners() -> [Vec3; 3] {
    [
        Vec3::new(-0.5, 1.0, 0.0),
        Vec3::new(-0.5, -0.5, 0.0),
        Vec3::new(2.0, 3.0, -0.0),
    ]
}

// ---------------------------------------------------------------------------------------------
// The cases

hard_case!(
    setup_geometry_covers_the_spherical_and_area_paths,
    "setup: the test geometry covers the spherical and the area paths",
    || {
        let tri = |t: [[f32; 3]; 3]| triangle_solid_angle_vos(d3(t[0]), d3(t[1]), d3(t[2]));
        let rect = |r: [[f32; 3]; 3]| rectangle_solid_angle(d3(r[0]), d3(r[1]), d3(r[2]));
        let (lo_t, hi_t) = (
            warp::SPHERICAL_TRIANGLE_MIN_SR as f64,
            warp::SPHERICAL_TRIANGLE_MAX_SR as f64,
        );
        let lo_r = warp::SPHERICAL_RECTANGLE_MIN_SR as f64;
        let (l, s, t) = (tri(TRI_LARGE), tri(tri_small()), tri(tri_tiny()));
        let (b, sm, tr) = (rect(RECT_BIG), rect(rect_small()), rect(rect_tiny()));
        collect([
            check(l > lo_t && l < hi_t && l > 4.0, || {
                format!("TRI_LARGE Ω = {l}")
            }),
            check(s > 1.5 * lo_t && s < 10.0 * lo_t, || {
                format!("tri_small Ω = {s}")
            }),
            check(t < 0.5 * lo_t, || format!("tri_tiny Ω = {t}")),
            check(b > 1.0, || format!("RECT_BIG Ω = {b}")),
            check(sm > 1.2 * lo_r && sm < 10.0 * lo_r, || {
                format!("rect_small Ω = {sm}")
            }),
            check(tr < 0.5 * lo_r, || format!("rect_tiny Ω = {tr}")),
        ])
    }
);

hard_case!(
    case_01_concentric_and_cosine_hemisphere_at_the_centre_are_exact,
    "1: concentric(½,½) = (0,0); cosine_hemisphere(½,½) = (0,0,1), pdf 1/π",
    || {
        let h = Vec2::splat(0.5);
        let p = warp::concentric_disk(h);
        let w = warp::cosine_hemisphere(h);
        let pdf = warp::cosine_hemisphere_pdf(w);
        collect([
            check(p.x == 0.0 && p.y == 0.0, || {
                format!("concentric(½,½) = {p:?}")
            }),
            check(w == Vec3::Z, || format!("cosine_hemisphere(½,½) = {w:?}")),
            check(pdf == std::f32::consts::FRAC_1_PI, || format!("pdf {pdf}")),
        ])
    }
);

hard_case!(
    case_02_cosine_hemisphere_on_the_square_boundary_is_finite_with_z_ge_0,
    "2: cosine_hemisphere on the square's boundary: z ≥ 0, finite",
    || {
        let mut r = vec![];
        let w = warp::cosine_hemisphere(Vec2::new(ONE_MINUS_EPS, 0.3));
        r.push(check(w.z >= 0.0 && w.is_finite(), || {
            format!("(1−ε, 0.3) → {w:?}")
        }));
        let edge = [0.0, 1.0 / 16_777_216.0, ONE_MINUS_EPS, 1.0];
        for i in 0..=4096 {
            let t = (i as f32 / 4096.0).min(ONE_MINUS_EPS);
            for &e in &edge {
                for u in [Vec2::new(e, t), Vec2::new(t, e)] {
                    let w = warp::cosine_hemisphere(u);
                    let pdf = warp::cosine_hemisphere_pdf(w);
                    let ok = w.is_finite()
                        && w.z >= 0.0
                        && (w.length() - 1.0).abs() <= 1e-6
                        && pdf >= 0.0
                        && pdf.is_finite();
                    r.push(check(ok, || format!("u={u:?} → {w:?}, pdf {pdf}")));
                }
            }
        }
        collect(r)
    }
);

hard_case!(
    case_03_uniform_sphere_at_u0_1e_8_has_radius_2e_4,
    "3: uniform_sphere(1e-8, u₁): r = 2.0e-4 within 1 %",
    || {
        collect((0..64).map(|i| {
            let u = Vec2::new(1e-8, (i as f32 + 0.5) / 64.0);
            let w = warp::uniform_sphere(u);
            let r = (w.x as f64).hypot(w.y as f64);
            check(rel_err(r, 2.0e-4) <= 0.01, || format!("u={u:?}: r = {r:e}"))
        }))
    }
);

hard_case!(
    case_04_uniform_cone_h_1e_7_has_pdf_1_59e6_and_spreads_over_the_cap,
    "4: uniform_cone h=1e-7: pdf 1.591549e6, samples spread over the cap",
    || {
        let h = 1e-7f32;
        let pdf = warp::uniform_cone_pdf(Vec3::Z, h);
        let mut r = vec![check(rel_err(pdf as f64, 1.591549e6) <= 1e-6, || {
            format!("pdf = {pdf}")
        })];
        let mut seen = std::collections::HashSet::new();
        let mut max_sin: f64 = 0.0;
        let n = 64;
        for u in grid(n) {
            let w = warp::uniform_cone(Vec2::new(u[0], u[1]), h);
            let s = (w.x as f64).hypot(w.y as f64);
            max_sin = max_sin.max(s);
            seen.insert((w.x.to_bits(), w.y.to_bits(), w.z.to_bits()));
            // sin θ = √(t(2 − t)) with t = u₀h: ≈ √(2u₀h) to 1e-3 relative.
            let want = (2.0 * u[0] as f64 * h as f64).sqrt();
            r.push(check(rel_err(s, want) <= 1e-3, || {
                format!("u={u:?}: sin θ = {s:e}, want {want:e}")
            }));
        }
        let cap = (2.0 * h as f64).sqrt();
        r.push(check(max_sin >= 0.99 * cap, || {
            format!("largest sin θ {max_sin:e}, cap {cap:e}")
        }));
        r.push(check(seen.len() == n * n, || {
            format!("{} distinct directions of {}", seen.len(), n * n)
        }));
        collect(r)
    }
);

hard_case!(
    case_05_cone_from_sin2_1e_8_has_h_5e_9_and_sin_theta_within_4_ulp,
    "5: cone from sin²θmax = 1e-8: h = 5e-9, finite pdf, sin θ = 1e-4·√u₀ within 4 ulp",
    || {
        let s2 = 1e-8f32;
        let h = warp::cone_h_from_sin2(s2);
        let pdf = warp::uniform_cone_pdf(Vec3::Z, h);
        let mut r = vec![
            check(rel_err(h as f64, 5e-9) <= 1e-6, || format!("h = {h:e}")),
            check(
                pdf.is_finite() && rel_err(pdf as f64, uniform_cone_pdf(h as f64)) <= 1e-6,
                || format!("pdf = {pdf:e}"),
            ),
        ];
        for u in grid(32)
            .into_iter()
            .chain([[1e-8, 0.3], [ONE_MINUS_EPS, 0.7]])
        {
            let w = warp::uniform_cone(Vec2::new(u[0], u[1]), h);
            let s = (w.x as f64).hypot(w.y as f64);
            let want = (s2 as f64 * u[0] as f64).sqrt();
            let tol = 4.0 * ulp(want as f32);
            r.push(check((s - want).abs() <= tol, || {
                format!("u={u:?}: sin θ = {s:e}, want {want:e} (±{tol:e})")
            }));
        }
        collect(r)
    }
);

hard_case!(
    case_06_uniform_cone_inverse_h_1e_7_recovers_u0_within_3e_7,
    "6: uniform_cone_inverse h=1e-7 recovers u₀ within 3e-7",
    || {
        let h = 1e-7f32;
        let mut r = vec![];
        for u in grid(64) {
            // From the f64 reference direction rounded to f32, and from the crate's own.
            let wr = uniform_cone(d2(u), h as f64);
            let wr = Vec3::new(wr[0] as f32, wr[1] as f32, wr[2] as f32);
            let wc = warp::uniform_cone(Vec2::new(u[0], u[1]), h);
            for (src, w) in [("reference", wr), ("crate", wc)] {
                let back = warp::uniform_cone_inverse(w, h);
                r.push(check((back.x - u[0]).abs() as f64 <= 3e-7, || {
                    format!("{src} w for u={u:?}: u₀ back = {}", back.x)
                }));
            }
        }
        collect(r)
    }
);

hard_case!(
    case_07_phong_lobe_n_1e6_keeps_99_percent_distinct_directions_and_peak_pdf_1_59e5,
    "7: phong_lobe n=1e6: ≥ 99 % distinct directions over 1e5 stratified u; peak pdf 1.5915e5",
    || {
        let n = 1e6f32;
        let count = 100_000;
        let mut seen = std::collections::HashSet::new();
        for i in 0..count {
            // u₀ stratified in 1e5 strata; u₁ along the golden-ratio sequence.
            let u0 = ((i as f64 + 0.5) / count as f64) as f32;
            let u1 = ((i as f64 * 0.618_033_988_749_894_9).fract()) as f32;
            let w = warp::phong_lobe(Vec2::new(u0, u1), n);
            seen.insert((w.x.to_bits(), w.y.to_bits(), w.z.to_bits()));
        }
        let peak = warp::phong_lobe_pdf(Vec3::Z, n);
        collect([
            check(seen.len() * 100 >= count * 99, || {
                format!("{} distinct directions of {count}", seen.len())
            }),
            check(rel_err(peak as f64, 1.5915e5) <= 1e-4, || {
                format!("peak pdf {peak}")
            }),
            check(
                rel_err(peak as f64, (n as f64 + 1.0) / std::f64::consts::TAU) <= 1e-5,
                || format!("peak pdf {peak}, want (n+1)/2π"),
            ),
        ])
    }
);

hard_case!(
    case_08_phong_lobe_n_0_is_the_uniform_hemisphere_and_u0_0_gives_pdf_0,
    "8: phong_lobe n=0 = uniform hemisphere; u₀ = 0 gives cos α = 0 and pdf 0",
    || {
        let mut r = vec![];
        for u in grid(64).into_iter().chain(border()) {
            let u = Vec2::new(u[0], u[1]);
            let p = warp::phong_lobe(u, 0.0);
            let h = warp::uniform_hemisphere(u);
            // z = u₀ in both; the Phong form goes through ln and expm1, so allow rounding.
            r.push(check((p.z - h.z).abs() <= 4e-7, || {
                format!("u={u:?}: phong z {} vs hemisphere z {}", p.z, h.z)
            }));
            r.push(check(dist3(dv3(p), dv3(h)) <= 2e-6, || {
                format!("u={u:?}: phong {p:?} vs hemisphere {h:?}")
            }));
            if p.z > 0.0 {
                let pdf = warp::phong_lobe_pdf(p, 0.0);
                r.push(check(
                    rel_err(pdf as f64, warp::uniform_hemisphere_pdf(Vec3::Z) as f64) <= 1e-6,
                    || format!("pdf n=0 at z={}: {pdf}", p.z),
                ));
            }
        }
        for n in [0.0f32, 1.0, 20.0, 1e6] {
            for u1 in [0.0f32, 0.3, ONE_MINUS_EPS] {
                let w = warp::phong_lobe(Vec2::new(0.0, u1), n);
                let pdf = warp::phong_lobe_pdf(w, n);
                r.push(check(w.z == 0.0 && pdf == 0.0 && w.is_finite(), || {
                    format!("n={n} u=(0,{u1}): w={w:?} pdf={pdf}")
                }));
            }
            let pdf = warp::phong_lobe_pdf(Vec3::X, n);
            r.push(check(pdf == 0.0, || {
                format!("phong_lobe_pdf(0, {n}) = {pdf}")
            }));
        }
        collect(r)
    }
);

hard_case!(
    case_09_uniform_triangle_barycentrics_are_nonnegative_including_u0_eq_u1,
    "9: uniform_triangle: b ≥ 0 for all u, including u₀ = u₁",
    || {
        let mut r = vec![];
        let mut check_b = |u: Vec2| {
            let b = warp::uniform_triangle(u);
            if !(b.x >= 0.0 && b.y >= 0.0 && b.z >= 0.0) {
                r.push(Err(format!("u={u:?}: b = {b:?}")));
            }
        };
        // The whole diagonal u₀ = u₁ of 24-bit values.
        for k in 0..(1u32 << 24) {
            let x = k as f32 / 16_777_216.0;
            check_b(Vec2::new(x, x));
        }
        // Next to the diagonal and next to 1.
        for k in 0..(1u32 << 16) {
            let x = (k << 8) as f32 / 16_777_216.0;
            let y = f32::from_bits(x.to_bits() + 1);
            check_b(Vec2::new(x, y));
            check_b(Vec2::new(y, x));
        }
        for i in 0..256u32 {
            for j in 0..256u32 {
                check_b(Vec2::new(
                    1.0 - i as f32 / 16_777_216.0,
                    1.0 - j as f32 / 16_777_216.0,
                ));
            }
        }
        for u in grid(512) {
            check_b(Vec2::new(u[0], u[1]));
        }
        collect(r)
    }
);

hard_case!(
    case_10_spherical_triangle_of_3e_7_sr_has_pdf_within_1e_4_of_one_over_omega,
    "10: spherical triangle with Ω ≈ 3e-7 sr: pdf within 1e-4 of 1/Ω",
    || {
        let mut r = vec![];
        let dir = normalize([0.3, -0.2, 1.0]);
        for d in [1.0f64, 1000.0] {
            // An equilateral triangle facing the origin, Ω ≈ 3e-7.
            let side = (4.0 * 3e-7 * d * d / 3f64.sqrt()).sqrt();
            let (t, b) = duff_frame(dir);
            let centre = scale(dir, d);
            let vtx = |k: f64| {
                let ang = k * std::f64::consts::TAU / 3.0;
                let rr = side / 3f64.sqrt();
                f3(add(
                    centre,
                    add(scale(t, rr * ang.cos()), scale(b, rr * ang.sin())),
                ))
            };
            let (a, bb, c) = (vtx(0.0), vtx(1.0), vtx(2.0));
            let omega = triangle_solid_angle_vos(d3(a), d3(bb), d3(c));
            let (a, bb, c) = (v(a), v(bb), v(c));
            r.push(check((omega - 3e-7).abs() < 1e-8, || {
                format!("setup Ω = {omega:e}")
            }));
            for u in grid(32) {
                let (w, pdf) = warp::spherical_triangle(Vec2::new(u[0], u[1]), a, bb, c);
                r.push(check(rel_err(pdf as f64 * omega, 1.0) <= 1e-4, || {
                    format!("d={d} u={u:?}: pdf·Ω = {}", pdf as f64 * omega)
                }));
                let pf = warp::spherical_triangle_pdf(w, a, bb, c);
                r.push(check(
                    pf == 0.0 || rel_err(pf as f64 * omega, 1.0) <= 1e-4,
                    || format!("d={d} u={u:?}: pdf fn·Ω = {}", pf as f64 * omega),
                ));
            }
            let centroid = ((a + bb + c) / 3.0).normalize();
            let pf = warp::spherical_triangle_pdf(centroid, a, bb, c);
            r.push(check(rel_err(pf as f64 * omega, 1.0) <= 1e-4, || {
                format!("d={d}: pdf at the centroid ·Ω = {}", pf as f64 * omega)
            }));
        }
        collect(r)
    }
);

hard_case!(
    case_11_degenerate_spherical_triangles_have_pdf_0_and_no_nan,
    "11: degenerate spherical triangles: pdf 0, no NaN",
    || {
        let mut r = vec![];
        let (p, q) = (Vec3::new(0.3, 0.1, 1.0), Vec3::new(-0.2, 0.4, 0.9));
        for (label, a, b, c) in degenerate_triangles() {
            for u in grid(4)
                .into_iter()
                .chain([[0.0, 0.0], [ONE_MINUS_EPS, ONE_MINUS_EPS]])
            {
                let (w, pdf) = warp::spherical_triangle(Vec2::new(u[0], u[1]), a, b, c);
                r.push(check(pdf == 0.0 && w.is_finite(), || {
                    format!("{label} u={u:?}: w={w:?} pdf={pdf}")
                }));
            }
            for w in [Vec3::Z, p.normalize(), q.normalize(), Vec3::NEG_Z, Vec3::X] {
                let pdf = warp::spherical_triangle_pdf(w, a, b, c);
                r.push(check(pdf == 0.0, || format!("{label}: pdf({w:?}) = {pdf}")));
                // The inverse is not specified for degenerate input: it must not panic.
                let _ = warp::spherical_triangle_inverse(w, a, b, c);
            }
        }
        collect(r)
    }
);

hard_case!(
    case_12_frame_at_nz_minus_0_9999999_is_orthonormal_and_minus_z_is_right_handed,
    "12: Frame at n_z = −0.9999999: orthonormal to 1e-6; n = −z right-handed",
    || {
        let mut r = vec![];
        for i in 0..1024 {
            let phi = i as f32 / 1024.0 * std::f32::consts::TAU;
            let z = -0.999_999_9f32;
            let s = (1.0 - z as f64 * z as f64).sqrt() as f32;
            let n = Vec3::new(s * phi.cos(), s * phi.sin(), z);
            let f = Frame::from_normal(n);
            let e = orthonormal_error(dv3(f.t), dv3(f.b), dv3(n));
            r.push(check(e <= 1e-6, || format!("n={n:?}: error {e:e}")));
        }
        for n in [Vec3::NEG_Z, Vec3::Z] {
            let f = Frame::from_normal(n);
            let handed = f.t.cross(f.b);
            r.push(check(
                handed == n && f.t.dot(f.b) == 0.0 && f.n == n,
                || format!("n={n:?}: t={:?} b={:?} t×b={handed:?}", f.t, f.b),
            ));
        }
        collect(r)
    }
);

hard_case!(
    case_14_every_warp_at_u_1_and_one_minus_eps_lands_in_its_domain,
    "14: every warp at u = (1,1) and (1−ε, 1−ε): a finite point in its domain",
    || {
        let mut r = vec![];
        for w in warps() {
            for u in [
                Vec2::ONE,
                Vec2::splat(ONE_MINUS_EPS),
                Vec2::new(1.0, 0.0),
                Vec2::new(0.0, 1.0),
            ] {
                let out = (w.s)(u);
                r.push((w.domain)(&out).map_err(|e| format!("{} u={u:?}: {e}", w.name)));
            }
        }
        collect(r)
    }
);

hard_case!(
    case_15_every_warp_and_pdf_at_nan_gives_same_bits_in_both_widths_and_documented_value,
    "15: every warp and pdf at NaN: no panic, same bits in both widths, documented value",
    || {
        let mut r = vec![];
        let nan = f32::NAN;
        // Not the canonical NaN: negative, with a payload, and a signalling one. A NaN that
        // merely propagates keeps its bits (and on x86 the first operand's), so only these show
        // that the output's NaN is made, not inherited.
        let odd = [f32::from_bits(0xffc0_1234), f32::from_bits(0x7f80_0001)];
        for w in warps() {
            let mut us = vec![Vec2::splat(nan), Vec2::new(nan, 0.5), Vec2::new(0.5, nan)];
            for x in odd {
                us.extend([Vec2::new(x, 0.5), Vec2::new(0.5, x), Vec2::new(x, nan)]);
            }
            for u in us {
                let s = (w.s)(u);
                // Eight lanes of u against the scalar.
                r.push(same_lanes(&format!("{} u={u:?}", w.name), (w.lanes)(&[u])));
                // "NaN in gives NaN out, always the canonical quiet NaN."
                r.push(canonical(&format!("{} u={u:?}", w.name), &s));
                let doc = if let Some(fixed) = w.fixed {
                    // "NaN u gives a pdf of 0" and "a fixed finite direction": +z for the
                    // triangle, the corner for the rectangle.
                    check(s[3] == 0.0 && Vec3::new(s[0], s[1], s[2]) == fixed, || {
                        format!("{} u={u:?}: {s:?}, documented pdf 0 at {fixed:?}", w.name)
                    })
                } else {
                    // "NaN in u gives NaN in every coordinate of the result" (either
                    // coordinate of u), and pdf 0.
                    check(
                        s[..w.nan_coords].iter().all(|x| x.is_nan()) && s[3] == 0.0,
                        || format!("{} u={u:?}: {s:?} is not all NaN with pdf 0", w.name),
                    )
                };
                r.push(doc);
            }
        }
        for f in funs() {
            let s = (f.s)(nan);
            r.push(same_lanes(&f.name, (f.lanes)(&[nan])));
            r.push(canonical(&f.name, &s));
            r.push((f.at_nan)(&s));
        }
        // Constant pdfs: same bits.
        r.push(same_lanes(
            "uniform_disk_pdf",
            check_lanes(
                &[Vec2::ZERO],
                warp::uniform_disk_pdf,
                warp::uniform_disk_pdf,
            ),
        ));
        r.push(same_lanes(
            "uniform_hemisphere_pdf",
            check_lanes(
                &[Vec3::Z],
                warp::uniform_hemisphere_pdf,
                warp::uniform_hemisphere_pdf,
            ),
        ));
        r.push(same_lanes(
            "uniform_sphere_pdf",
            check_lanes(
                &[Vec3::Z],
                warp::uniform_sphere_pdf,
                warp::uniform_sphere_pdf,
            ),
        ));
        collect(r)
    }
);

// 15b: bad inputs in mixed lanes: each lane equals the scalar on its own input.
hard_case!(
    case_15b_mixed_bad_inputs_across_lanes_equal_the_scalar_bit_for_bit,
    "15b: mixed bad inputs across lanes: lane i = scalar on lane i's input, bit for bit",
    || {
        let mut r = vec![];
        let vals = [
            f32::NAN,
            -1.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            1.0,
            ONE_MINUS_EPS,
            -0.0,
            0.5,
        ];
        // One packet: lane i holds input i.
        let lanes: [Vec2; 8] = std::array::from_fn(|i| Vec2::new(vals[i], vals[(i * 3 + 1) % 8]));
        for w in warps() {
            r.push(same_lanes(&w.name, (w.lanes)(&lanes)));
        }
        for f in funs() {
            r.push(same_lanes(&f.name, (f.lanes)(&vals)));
        }
        collect(r)
    }
);

hard_case!(
    case_17_edge_on_rectangle_has_pdf_0_or_an_exact_area_fallback,
    "17: rectangle seen edge-on: pdf 0 or an exact area fallback, never NaN",
    || {
        let mut r = vec![];
        let ex = Vec3::new(1.0, 0.0, 0.0);
        let ey = Vec3::new(0.0, 1.0, 0.0);
        for corner in edge_on_corners() {
            for u in grid(8) {
                let (p, pdf) = warp::spherical_rectangle(Vec2::new(u[0], u[1]), corner, ex, ey);
                r.push(check(pdf == 0.0 && p.is_finite(), || {
                    format!("corner {corner:?} u={u:?}: p={p:?} pdf={pdf}")
                }));
            }
            for w in [
                Vec3::Z,
                Vec3::X,
                Vec3::new(0.0, 1.0, 0.0),
                Vec3::new(0.6, 0.8, 0.0),
            ] {
                let pdf = warp::spherical_rectangle_pdf(w, corner, ex, ey);
                r.push(check(pdf == 0.0, || {
                    format!("corner {corner:?}: pdf({w:?}) = {pdf}")
                }));
            }
        }
        // Nearly edge-on: pdf 0, 1/Ω where it is sampled spherically (above the threshold), or
        // the exact converted pdf; never NaN or ∞.
        for z in [1e-3f32, 1e-6, 1e-12, 1e-30, 1e-40] {
            let corner = Vec3::new(-0.5, 1.0, z);
            let n = cross(dv3(ex), dv3(ey));
            let omega = rectangle_solid_angle(dv3(corner), dv3(ex), dv3(ey));
            for u in grid(8) {
                let (p, pdf) = warp::spherical_rectangle(Vec2::new(u[0], u[1]), corner, ex, ey);
                let w = normalize(dv3(p));
                let want = area_pdf_to_solid_angle(w, dv3(corner), n, 1.0);
                let spherical = omega >= warp::SPHERICAL_RECTANGLE_MIN_SR as f64
                    && rel_err(pdf as f64, 1.0 / omega) <= 1e-5;
                let ok = pdf.is_finite()
                    && p.is_finite()
                    && (pdf == 0.0 || spherical || rel_err(pdf as f64, want) <= 1e-4);
                r.push(check(ok, || {
                    format!("z={z:e} u={u:?}: p={p:?} pdf={pdf:e}, converted {want:e}")
                }));
            }
        }
        collect(r)
    }
);

// Documented: u is clamped to [0, 1]², so bad u gives the same point as the clamped u, and a
// finite point of the domain.
hard_case!(
    doc_bad_u_is_clamped_to_the_unit_square,
    "doc: u = −1, ±∞, 1, huge, −0 are clamped: same point as clamped u, in the domain",
    || {
        let mut r = vec![];
        let mut pairs = vec![];
        for &a in &BAD {
            for &b in BAD.iter().chain(&[0.3f32]) {
                pairs.push(Vec2::new(a, b));
                pairs.push(Vec2::new(b, a));
            }
        }
        for w in warps() {
            for &u in &pairs {
                let out = (w.s)(u);
                r.push((w.domain)(&out).map_err(|e| format!("{} u={u:?}: {e}", w.name)));
                let clamped = (w.s)(Vec2::new(clamp01(u.x), clamp01(u.y)));
                r.push(check(out == clamped, || {
                    format!("{} u={u:?}: {out:?} ≠ clamped {clamped:?}", w.name)
                }));
            }
        }
        collect(r)
    }
);

hard_case!(
    doc_cone_h_le_0_gives_the_axis_and_pdf_0_and_h_above_2_clamps,
    "doc: cone h = 0 and h < 0: pdf 0, samples on the axis; h > 2 clamps to 2",
    || {
        let mut r = vec![];
        for h in [0.0f32, -0.0, -1.0, f32::NEG_INFINITY] {
            let pdf = warp::uniform_cone_pdf(Vec3::Z, h);
            r.push(check(pdf == 0.0, || {
                format!("uniform_cone_pdf({h}) = {pdf}")
            }));
            for u in grid(4) {
                let w = warp::uniform_cone(Vec2::new(u[0], u[1]), h);
                r.push(check(w.x == 0.0 && w.y == 0.0 && w.z == 1.0, || {
                    format!("uniform_cone({u:?}, {h}) = {w:?}")
                }));
            }
        }
        for h in [2.5f32, 1e30, f32::INFINITY] {
            r.push(check(
                warp::uniform_cone_pdf(Vec3::Z, h) == warp::uniform_cone_pdf(Vec3::Z, 2.0),
                || {
                    format!(
                        "uniform_cone_pdf({h}) = {}",
                        warp::uniform_cone_pdf(Vec3::Z, h)
                    )
                },
            ));
            for u in grid(4) {
                let u = Vec2::new(u[0], u[1]);
                r.push(check(
                    warp::uniform_cone(u, h) == warp::uniform_cone(u, 2.0),
                    || format!("uniform_cone({u:?}, {h}) ≠ h = 2"),
                ));
            }
        }
        // The h helpers clamp.
        let hs = [
            ("cone_h_from_sin2(−1)", warp::cone_h_from_sin2(-1.0), 0.0),
            ("cone_h_from_sin2(2)", warp::cone_h_from_sin2(2.0), 1.0),
            ("cone_h_from_sin2(1)", warp::cone_h_from_sin2(1.0), 1.0),
            ("cone_h_from_sin2(0)", warp::cone_h_from_sin2(0.0), 0.0),
            ("cone_h_from_cos(2)", warp::cone_h_from_cos(2.0), 0.0),
            ("cone_h_from_cos(−3)", warp::cone_h_from_cos(-3.0), 2.0),
            ("cone_h_from_cos(−1)", warp::cone_h_from_cos(-1.0), 2.0),
        ];
        for (name, got, want) in hs {
            r.push(check(got == want, || {
                format!("{name} = {got}, want {want}")
            }));
        }
        collect(r)
    }
);

hard_case!(
    doc_phong_n_is_clamped_to_0_1e20_and_pdf_is_0_below_the_horizon,
    "doc: Phong n is clamped to [0, 1e20]; the pdf is 0 at and below the horizon",
    || {
        let mut r = vec![];
        for u in grid(8) {
            let u = Vec2::new(u[0], u[1]);
            r.push(check(
                warp::phong_lobe(u, -3.0) == warp::phong_lobe(u, 0.0),
                || format!("phong_lobe({u:?}, −3) ≠ n = 0"),
            ));
            let big = warp::phong_lobe(u, f32::INFINITY);
            r.push(check(
                big == warp::phong_lobe(u, 1e20) && big.is_finite(),
                || format!("phong_lobe({u:?}, ∞) = {big:?}"),
            ));
        }
        for c in [0.1f32, 0.5, 1.0] {
            r.push(check(
                warp::phong_lobe_pdf(Vec3::Z * c, -3.0) == warp::phong_lobe_pdf(Vec3::Z * c, 0.0),
                || format!("phong_lobe_pdf({c}, −3)"),
            ));
            let p = warp::phong_lobe_pdf(Vec3::Z * c, f32::INFINITY);
            r.push(check(p.is_finite() || p == f32::INFINITY, || {
                format!("pdf({c}, ∞) = {p}")
            }));
        }
        for c in [0.0f32, -0.0, -0.5, -1.0, f32::NEG_INFINITY] {
            for n in [0.0f32, 1.0, 20.0] {
                let p = warp::phong_lobe_pdf(Vec3::new(0.0, 0.0, c), n);
                r.push(check(p == 0.0, || {
                    format!("phong_lobe_pdf({c}, {n}) = {p}")
                }));
            }
        }
        collect(r)
    }
);

hard_case!(
    doc_pdfs_are_0_outside_their_support,
    "doc: pdfs are 0 outside their support",
    || {
        let mut r = vec![];
        for x in [0.0f32, -0.0, -0.5, -1.0, f32::NEG_INFINITY] {
            let p = warp::cosine_hemisphere_pdf(Vec3::new(0.0, 0.0, x));
            r.push(check(p == 0.0, || {
                format!("cosine_hemisphere_pdf({x}) = {p}")
            }));
        }
        for x in [1.0f32, -1.0, 1.5, -1.5, f32::INFINITY, f32::NEG_INFINITY] {
            let p = warp::tent_pdf(x);
            r.push(check(p == 0.0, || format!("tent_pdf({x}) = {p}")));
        }
        for b in [
            Vec3::new(0.7, 0.7, -0.4),
            Vec3::new(-0.1, 0.5, 0.6),
            Vec3::new(0.5, -1e-30, 0.5),
            Vec3::new(0.5, 0.5, -1e-30),
            Vec3::new(f32::INFINITY, 0.0, f32::NEG_INFINITY),
        ] {
            let p = warp::uniform_triangle_pdf(b);
            r.push(check(p == 0.0, || {
                format!("uniform_triangle_pdf({b:?}) = {p}")
            }));
        }
        let t = tri_small().map(v);
        let rc = RECT_BIG.map(v);
        for w in [Vec3::NEG_Z, Vec3::X, -(t[0] + t[1] + t[2]).normalize()] {
            let p = warp::spherical_triangle_pdf(w, t[0], t[1], t[2]);
            r.push(check(p == 0.0, || {
                format!("spherical_triangle_pdf({w:?}) = {p}")
            }));
            let p = warp::spherical_rectangle_pdf(w, rc[0], rc[1], rc[2]);
            r.push(check(p == 0.0, || {
                format!("spherical_rectangle_pdf({w:?}) = {p}")
            }));
        }
        collect(r)
    }
);

hard_case!(
    doc_degenerate_rectangles_give_pdf_0_and_the_corner,
    "doc: degenerate rectangles (zero edge, edge-on): pdf 0, point = corner",
    || {
        let mut r = vec![];
        let corner = Vec3::new(-0.5, -0.5, 1.0);
        let cases = [
            ("ex = 0", Vec3::ZERO, Vec3::Y),
            ("ey = 0", Vec3::X, Vec3::ZERO),
            ("both 0", Vec3::ZERO, Vec3::ZERO),
            ("NaN edge", Vec3::new(f32::NAN, 0.0, 0.0), Vec3::Y),
            ("infinite edge", Vec3::new(f32::INFINITY, 0.0, 0.0), Vec3::Y),
        ];
        for (label, ex, ey) in cases {
            for u in grid(4) {
                let (p, pdf) = warp::spherical_rectangle(Vec2::new(u[0], u[1]), corner, ex, ey);
                r.push(check(pdf == 0.0 && p == corner, || {
                    format!("{label} u={u:?}: p={p:?} pdf={pdf}")
                }));
            }
            let pdf = warp::spherical_rectangle_pdf(Vec3::Z, corner, ex, ey);
            r.push(check(pdf == 0.0, || format!("{label}: pdf fn = {pdf}")));
        }
        collect(r)
    }
);

hard_case!(
    doc_inverses_of_the_centre_azimuth_below_1_and_zero_normal_frame,
    "doc: inverses: p = 0 ↦ (½, ½); azimuth fractions stay below 1; zero normal gives the +z frame",
    || {
        let mut r = vec![];
        let u = warp::concentric_disk_inverse(Vec2::ZERO);
        r.push(check(u == Vec2::splat(0.5), || {
            format!("concentric_disk_inverse(0) = {u:?}")
        }));
        let tiny = -1e-30f32;
        let az = [
            (
                "polar_disk_inverse",
                warp::polar_disk_inverse(Vec2::new(1.0, tiny)).y,
            ),
            (
                "uniform_sphere_inverse",
                warp::uniform_sphere_inverse(Vec3::new(1.0, tiny, 0.0)).y,
            ),
            (
                "uniform_hemisphere_inverse",
                warp::uniform_hemisphere_inverse(Vec3::new(1.0, tiny, 0.0)).y,
            ),
            (
                "uniform_cone_inverse",
                warp::uniform_cone_inverse(Vec3::new(0.1, tiny, 0.99), 0.3).y,
            ),
            (
                "phong_lobe_inverse",
                warp::phong_lobe_inverse(Vec3::new(0.1, tiny, 0.99), 5.0).y,
            ),
        ];
        for (name, y) in az {
            r.push(check((0.0..1.0).contains(&y), || {
                format!("{name}: azimuth {y}")
            }));
        }
        let f = Frame::from_normal(Vec3::ZERO);
        r.push(check(f.t == Vec3::X && f.b == Vec3::Y, || {
            format!("zero normal: t={:?} b={:?}", f.t, f.b)
        }));
        let x = warp::tent_inverse(5.0);
        let y = warp::tent_inverse(-5.0);
        r.push(check(x == 1.0 && y == 0.0, || {
            format!("tent_inverse(±5) = {x}, {y}")
        }));
        collect(r)
    }
);

hard_case!(
    doc_degenerate_triangle_gives_plus_z_and_edge_on_rectangle_gives_the_corner,
    "doc: degenerate triangle → direction +z; edge-on rectangle → point = corner",
    || {
        let mut r = vec![];
        for (label, a, b, c) in degenerate_triangles() {
            for u in grid(2) {
                let (w, pdf) = warp::spherical_triangle(Vec2::new(u[0], u[1]), a, b, c);
                r.push(check(w == Vec3::Z, || {
                    format!("triangle {label} u={u:?}: w={w:?} (pdf {pdf}), documented +z")
                }));
            }
        }
        let (ex, ey) = (Vec3::X, Vec3::Y);
        for corner in edge_on_corners() {
            for u in grid(2) {
                let (p, pdf) = warp::spherical_rectangle(Vec2::new(u[0], u[1]), corner, ex, ey);
                r.push(check(p == corner, || {
                        format!(
                            "edge-on rectangle at {corner:?} u={u:?}: p={p:?} (pdf {pdf}), documented the corner"
                        )
                    }));
            }
        }
        collect(r)
    }
);
