//! Packet == scalar, bit for bit, in both packet widths (8 and 16 lanes), on 2¹⁶ random inputs
//! (2¹² when emulated) mixed with the hard inputs (NaN, ±∞, 0, −0, 1, 1 − 2⁻²⁴, subnormals, huge values):
//!
//! - every sampler of the registry: sample, pdf and inverse, at the samples and at arbitrary
//!   points;
//! - the warps with parameters or geometry, with a different parameter or light in every lane, so
//!   that one packet mixes code paths (spherical and area sampling, inside and outside a
//!   support), and the frame.

use crate::common::{TestRng, lanes, random_inputs};
use glam::{Vec2, Vec3};
use mcsample::frame::Frame;
use mcsample::verify::registry;
use mcsample::verify::{check_lanes, check_lanes16};
use mcsample::warp::{self, ONE_MINUS_EPS};
use mcsample::x8::{F32x8, Vec2x8};
use mcsample::x16::{F32x16, Vec2x16};

const N: usize = 1 << 16;

/// Three vertices (or a corner and two edges).
type Tri = (Vec3, Vec3, Vec3);

const HARD: [f32; 16] = [
    0.0,
    -0.0,
    1.0,
    ONE_MINUS_EPS,
    0.5,
    1e-8,
    -1.0,
    2.0,
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    1e-40,
    f32::MAX,
    f32::MIN_POSITIVE,
    0.25,
    0.75,
];

// Inputs, drawn from the shared test generator.

/// Mostly in [0, 1), one time in eight a hard value.
fn u1(g: &mut TestRng) -> f32 {
    if g.below(8) == 0 { hard(g) } else { g.u01() }
}
fn hard(g: &mut TestRng) -> f32 {
    HARD[g.below(16) as usize]
}
fn u2(g: &mut TestRng) -> Vec2 {
    let x = u1(g);
    Vec2::new(x, u1(g))
}
/// Log-uniform in [lo, hi], sometimes a hard value.
fn param(g: &mut TestRng, lo: f32, hi: f32) -> f32 {
    if g.below(8) == 0 {
        hard(g)
    } else {
        lo * (hi / lo).powf(g.u01())
    }
}
fn dir(g: &mut TestRng) -> Vec3 {
    let z = 1.0 - 2.0 * g.u01();
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = std::f32::consts::TAU * g.u01();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}
/// Mostly unit directions, sometimes a hard component.
fn w(g: &mut TestRng) -> Vec3 {
    let mut w = dir(g);
    if g.below(8) == 0 {
        w[g.below(3) as usize] = hard(g);
    }
    w
}
/// Triangles of every size: far and tiny, near and huge, degenerate, with hard components.
fn triangle(g: &mut TestRng) -> Tri {
    let centre = dir(g) * param(g, 1e-2, 1e3);
    let size = param(g, 1e-6, 1e2);
    let mut v = [
        centre + dir(g) * size,
        centre + dir(g) * size,
        centre + dir(g) * size,
    ];
    match g.below(16) {
        0 => v[1] = v[0],
        1 => v[2] = v[0] * 2.0,
        2 => v[g.below(3) as usize].x = hard(g),
        _ => {}
    }
    (v[0], v[1], v[2])
}
/// Rectangles (orthogonal edges) of every size, including edge-on ones.
fn rectangle(g: &mut TestRng) -> Tri {
    let corner = dir(g) * param(g, 1e-2, 1e3);
    let f = Frame::from_normal(dir(g));
    let mut ex = f.t * param(g, 1e-5, 1e2);
    let ey = f.b * param(g, 1e-5, 1e2);
    match g.below(16) {
        // Edge-on: the shading point lies in the rectangle's plane.
        0 => return (ex * 0.3 + ey * -0.2, ex, ey),
        1 => ex = Vec3::ZERO,
        _ => {}
    }
    (corner, ex, ey)
}

#[test]
fn every_registered_sampler_matches_its_scalar_twin_bit_for_bit() {
    let mut g = TestRng::new(5);
    let us: Vec<Vec2> = (0..random_inputs(N)).map(|_| u2(&mut g)).collect();
    let mut failures = Vec::new();
    for s in registry::registry() {
        let name = s.name();
        lanes!(&mut failures, &name, &us, |u: V2| s.sample(u));
        // Points: half the samples, half arbitrary directions with hard components.
        let xs: Vec<Vec3> = us
            .iter()
            .map(|&u| {
                if g.below(2) == 0 {
                    s.sample(u).0
                } else {
                    w(&mut g)
                }
            })
            .collect();
        lanes!(&mut failures, &name, &xs, |x: V3| s.pdf(x));
        lanes!(&mut failures, &name, &xs, |x: V3| s.inverse(x));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn warps_with_a_different_parameter_in_every_lane_match_their_scalar_twins() {
    let mut g = TestRng::new(7);
    let us: Vec<Vec2> = (0..N).map(|_| u2(&mut g)).collect();
    let xs: Vec<f32> = (0..N).map(|_| u1(&mut g)).collect();
    let ws: Vec<Vec3> = (0..N).map(|_| w(&mut g)).collect();
    let mut f = Vec::new();
    let f = &mut f;

    let hs: Vec<f32> = (0..N).map(|_| param(&mut g, 1e-8, 2.0)).collect();
    lanes!(f, "cone_h_from_cos", &xs, warp::cone_h_from_cos);
    lanes!(f, "cone_h_from_sin2", &xs, warp::cone_h_from_sin2);
    let uh: Vec<(Vec2, f32)> = us.iter().copied().zip(hs.iter().copied()).collect();
    lanes!(
        f,
        "uniform_cone",
        &uh,
        |(u, h): (V2, L)| warp::uniform_cone(u, h)
    );
    let wh: Vec<(Vec3, f32)> = ws.iter().copied().zip(hs.iter().copied()).collect();
    lanes!(f, "uniform_cone_inverse", &wh, |(w, h): (V3, L)| {
        warp::uniform_cone_inverse(w, h)
    });
    lanes!(f, "uniform_cone_pdf", &wh, |(w, h): (V3, L)| {
        warp::uniform_cone_pdf(w, h)
    });

    let ns: Vec<f32> = (0..N).map(|_| param(&mut g, 1e-3, 1e7)).collect();
    let un: Vec<(Vec2, f32)> = us.iter().copied().zip(ns.iter().copied()).collect();
    lanes!(f, "phong_lobe", &un, |(u, n): (V2, L)| warp::phong_lobe(
        u, n
    ));
    // The hard values as cos α, in directions whose x and y are hard values too.
    let cn: Vec<(Vec3, f32)> = (xs.iter().zip(&ws).zip(&ns))
        .map(|((&c, w), &n)| (Vec3::new(w.x, w.y, c), n))
        .collect();
    lanes!(f, "phong_lobe_pdf", &cn, |(w, n): (V3, L)| {
        warp::phong_lobe_pdf(w, n)
    });
    let wn: Vec<(Vec3, f32)> = ws.iter().copied().zip(ns.iter().copied()).collect();
    lanes!(f, "phong_lobe_inverse", &wn, |(w, n): (V3, L)| {
        warp::phong_lobe_inverse(w, n)
    });

    // Spherical polygons: a different triangle in every lane. Directions are drawn towards the
    // polygon half of the time, so inside and outside both occur.
    let tris: Vec<Tri> = (0..N).map(|_| triangle(&mut g)).collect();
    let st: Vec<(Vec2, Tri)> = us.iter().copied().zip(tris.iter().copied()).collect();
    lanes!(f, "spherical_triangle", &st, |(u, (a, b, c)): (
        V2,
        (V3, V3, V3)
    )| {
        warp::spherical_triangle(u, a, b, c)
    });
    let tw: Vec<(Vec3, Tri)> = st
        .iter()
        .zip(&ws)
        .map(|(&(u, (a, b, c)), &w)| {
            let toward = warp::spherical_triangle(u, a, b, c).0;
            (if g.below(2) == 0 { toward } else { w }, (a, b, c))
        })
        .collect();
    lanes!(f, "spherical_triangle_pdf", &tw, |(w, (a, b, c)): (
        V3,
        (V3, V3, V3)
    )| {
        warp::spherical_triangle_pdf(w, a, b, c)
    });
    lanes!(f, "spherical_triangle_inverse", &tw, |(w, (a, b, c)): (
        V3,
        (V3, V3, V3)
    )| {
        warp::spherical_triangle_inverse(w, a, b, c)
    });

    let rects: Vec<Tri> = (0..N).map(|_| rectangle(&mut g)).collect();
    let sr: Vec<(Vec2, Tri)> = us.iter().copied().zip(rects.iter().copied()).collect();
    lanes!(f, "spherical_rectangle", &sr, |(u, (s, ex, ey)): (
        V2,
        (V3, V3, V3)
    )| {
        warp::spherical_rectangle(u, s, ex, ey)
    });
    let rp: Vec<((Vec3, Vec3), Tri)> = sr
        .iter()
        .zip(&ws)
        .map(|(&(u, (s, ex, ey)), &w)| {
            let p = warp::spherical_rectangle(u, s, ex, ey).0;
            let toward = p.normalize_or_zero();
            ((if g.below(2) == 0 { toward } else { w }, p), (s, ex, ey))
        })
        .collect();
    lanes!(f, "spherical_rectangle_pdf", &rp, |(
        (w, _),
        (s, ex, ey),
    ): (
        (V3, V3),
        (V3, V3, V3)
    )| {
        warp::spherical_rectangle_pdf(w, s, ex, ey)
    });
    lanes!(f, "spherical_rectangle_inverse", &rp, |(
        (_, p),
        (s, ex, ey),
    ): (
        (V3, V3),
        (V3, V3, V3)
    )| {
        warp::spherical_rectangle_inverse(p, s, ex, ey)
    });

    // Frames: construction and both transforms.
    let nv: Vec<(Vec3, Vec3)> = ws.iter().copied().zip(ws.iter().rev().copied()).collect();
    lanes!(f, "Frame", &nv, |(n, v): (V3, V3)| {
        let fr = Frame::from_normal(n);
        (fr.t, fr.b, (fr.to_local(v), fr.to_world(v)))
    });

    assert!(
        f.is_empty(),
        "{} functions differ between widths:\n{}",
        f.len(),
        f.join("\n")
    );
}

/// The check itself must be able to fail: a packet function that is off by one ulp in one lane.
#[test]
fn negative_control_one_lane_off_by_one_ulp_is_caught() {
    let mut g = TestRng::new(11);
    let us: Vec<Vec2> = (0..64).map(|_| g.u2()).collect();
    let broken = |u: Vec2x8| {
        let mut p = warp::concentric_disk(u);
        let mut x = p.x.to_array();
        x[5] = f32::from_bits(x[5].to_bits() ^ 1);
        p.x = F32x8::new(x);
        p
    };
    let err = check_lanes(&us, broken, warp::concentric_disk).unwrap_err();
    assert_eq!(err.lane, 5);
    let broken16 = |u: Vec2x16| {
        let mut p = warp::concentric_disk(u);
        let mut x = p.x.to_array();
        x[13] = f32::from_bits(x[13].to_bits() ^ 1);
        p.x = F32x16::new(x);
        p
    };
    let err = check_lanes16(&us, broken16, warp::concentric_disk).unwrap_err();
    assert_eq!((err.lane, err.mismatches, err.checked), (13, 4, 64));
}

/// The two lane operations whose scalar and packet forms are written differently: `xorsign`
/// (bits in both widths; a multiply by ±1 in the default) and `select_finite` (arithmetic on
/// k ∈ {0, 1} in the scalar form, a blend in the packet form). Both widths, and the facts they
/// stand for: `xorsign` is `copysign` wherever the sign bit of `self` is clear, and
/// `select_finite` is `select` for finite operands but for the sign of a zero.
#[test]
fn xorsign_and_select_finite_agree_with_their_definitions_in_both_widths() {
    use mcsample::lane::Lane;
    let finite: Vec<f32> = HARD
        .iter()
        .copied()
        .filter(|x| x.is_finite())
        .chain([-0.3, 3e-39, -f32::MAX, 7.5])
        .collect();
    let all: Vec<f32> = HARD.iter().copied().chain(finite.iter().copied()).collect();
    let pack = |x: f32| F32x8::splat(x);
    let lane0 = |v: F32x8| v.to_array()[0];
    for &x in &all {
        for &s in &all {
            let flipped = Lane::xorsign(x, s);
            let expect = f32::from_bits(x.to_bits() ^ (s.to_bits() & 0x8000_0000));
            assert_eq!(flipped.to_bits(), expect.to_bits(), "xorsign({x}, {s})");
            assert_eq!(lane0(pack(x).xorsign(pack(s))).to_bits(), expect.to_bits());
            if x.is_sign_positive() {
                assert_eq!(flipped.to_bits(), Lane::copysign(x, s).to_bits());
            }
        }
    }
    for &a in &finite {
        for &b in &finite {
            for m in [false, true] {
                let want = if m { a } else { b };
                let scalar = <f32 as Lane>::select_finite(m, a, b);
                let mask = F32x8::splat(f32::from_bits(if m { u32::MAX } else { 0 }));
                let packet = lane0(<F32x8 as Lane>::select_finite(mask, pack(a), pack(b)));
                assert_eq!(
                    packet.to_bits(),
                    want.to_bits(),
                    "packet select_finite({m}, {a}, {b})"
                );
                if want != 0.0 {
                    assert_eq!(
                        scalar.to_bits(),
                        want.to_bits(),
                        "select_finite({m}, {a}, {b})"
                    );
                } else {
                    assert_eq!(scalar, 0.0);
                }
            }
        }
    }
}

/// The registry's tent is a pair, one 2D sample: NaN in either coordinate of u makes both
/// coordinates the canonical quiet NaN (whatever NaN came in) and the pdf 0, in both widths, and
/// the other coordinate's tent is untouched otherwise.
#[test]
fn the_tent_pair_drops_both_coordinates_at_nan_in_either() {
    let canonical = f32::NAN.to_bits();
    let odd = [
        f32::NAN,
        f32::from_bits(0xffc0_1234),
        f32::from_bits(0x7f80_0001),
    ];
    let s = registry::Sampler::from(mcsample::warp::TentPair);
    for x in odd {
        for u in [Vec2::new(x, 0.3), Vec2::new(0.3, x), Vec2::splat(x)] {
            let (t, pdf) = s.sample(u);
            assert_eq!(
                [t.x.to_bits(), t.y.to_bits()],
                [canonical; 2],
                "tent pair at {u:?}: {t:?}"
            );
            assert_eq!((t.z, pdf), (0.0, 0.0), "tent pair at {u:?}");
            let (t8, pdf8) = s.sample(Vec2x8::splat(u));
            for (i, v) in t8.to_array().into_iter().enumerate() {
                assert_eq!(
                    v.to_array().map(f32::to_bits),
                    t.to_array().map(f32::to_bits)
                );
                assert_eq!(pdf8.to_array()[i].to_bits(), pdf.to_bits());
            }
        }
    }
    // Finite u: each coordinate is the tent of its own u.
    let (t, _) = s.sample(Vec2::new(0.3, 0.9));
    assert_eq!((t.x, t.y), (warp::tent(0.3), warp::tent(0.9)));
}

/// Without AVX-512 a sixteen-wide value splits into its lanes 0..8 and 8..16 and joins back to
/// itself bit for bit; with AVX-512 it runs whole, as every narrower lane does. The lanes checks
/// above catch a wrong join in the long samplers; this catches a split that never happens (a
/// wrong `cfg`), which they cannot see.
#[test]
fn sixteen_lanes_split_only_without_avx512() {
    use mcsample::lane::{Lanes, V3};
    use mcsample::math::Math;
    use mcsample::point::{Join, Split};
    assert_eq!(<F32x16 as Math>::SPLIT, !cfg!(target_feature = "avx512f"));
    const { assert!(!<F32x8 as Math>::SPLIT && !<f32 as Math>::SPLIT && !<f64 as Math>::SPLIT) };
    let x = F32x16::new(std::array::from_fn(|i| i as f32 - 7.5));
    let v = V3::new(x, x * F32x16::splat(-2.0), F32x16::splat(f32::NAN));
    let (lo, hi) = v.halves();
    let half = <<F32x16 as Math>::Half as Lanes>::WIDTH;
    assert_eq!(half, if <F32x16 as Math>::SPLIT { 8 } else { 16 });
    for i in 0..16 {
        let got = if i < half {
            lo.x.lane(i)
        } else {
            hi.x.lane(i - half)
        };
        assert_eq!(got.to_bits(), x.to_array()[i].to_bits(), "lane {i}");
    }
    let back: V3<F32x16> = Join::join(lo, hi);
    for (a, b) in [(back.x, v.x), (back.y, v.y), (back.z, v.z)] {
        assert_eq!(
            a.to_array().map(f32::to_bits),
            b.to_array().map(f32::to_bits)
        );
    }
}
