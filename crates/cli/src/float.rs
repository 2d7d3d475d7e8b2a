//! The float path: `rcagd build --float` builds an op's construction with the library's
//! `f64` instantiation instead of the exact one (issue 20, item 3).
//!
//! Every construction of the library is generic over [`rcagd_algebra::Scalar`], and so
//! is every op builder that has a float path: ONE builder per op, generic over
//! [`crate::ops::arith::OpScalar`], reads the same checked parameters ([`crate::ops::OpArgs`]),
//! converts them to the scalar, calls the library and wraps the result in the same
//! [`Object`]s. The op registry ([`crate::ops`]) instantiates it with `Rational`; this
//! module is a second, smaller registry that instantiates it with `f64`. Two things keep a
//! float result honest:
//!
//! * the control points are stored as the *exact binary values* of the `f64` results
//!   (dyadic rationals, [`Scalar::to_rational`]), so every exporter works unchanged and
//!   nothing is rounded a second time;
//! * the certificates are the library's `f64` ones (`exact = false`: an identity checked
//!   to a tolerance scaled by the data, not a proof), and every object carries the value
//!   `arithmetic = "f64"` ([`ARITHMETIC`]) in its JSON `values`, so a float result cannot
//!   be mistaken for an exact one.
//!
//! The ops whose `f64` construction cancels digits (`common_transversals`,
//! `sphere_family_envelope`, `sphere_family_recognize`) run in double-double
//! ([`DoubleDouble`], about 106 bits) and round their curves and patches once to `f64` at
//! the end ([`crate::ops::arith::OpScalar`]): the objects are `f64` numbers as the others.
//!
//! Ops without a float builder are refused by `rcagd build --float` (see
//! [`NO_FLOAT_PATH`] for why each topic has none). Where the exact op first solves an
//! exact-only sub-problem on its *input* (a rational point on a quadric), the builder
//! does the same exact step on the input and runs the construction itself in `f64`
//! (said per op in [`FloatOp::note`]).

use crate::model::Object;
use crate::ops::{self, OpArgs, OpError};
use num_traits::Zero;
#[cfg(doc)]
use rcagd_algebra::Scalar;
use rcagd_algebra::{DoubleDouble, Rational};
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The refusal of `ph_curve`'s and `ph_helix`'s display objects by the float path (the
/// fuzzer's exact-against-`f64` check tells this refusal from a failure by it).
pub const DISPLAY_OBJECTS_REFUSED: &str =
    "the display objects (frame, comb, feed) have no float path: build them without --float";

/// Whether `key` of an object of op `op` asks for display objects that the float path
/// refuses ([`DISPLAY_OBJECTS_REFUSED`]): the frames, combs and feed marks of `ph_curve`
/// and `ph_helix` and their sampling parameters.
pub fn is_display_param(op: &str, key: &str) -> bool {
    (op == "ph_curve" || op == "ph_helix")
        && ["frame", "comb", "feed", "samples", "frame_length"].contains(&key)
}

/// The words of a float path's refusal of an input whose f64 build is not shown to agree
/// with the exact one to 1e-12 (an open finding; the op's note names the inputs).
pub const UNVERIFIED_REFUSED: &str = "has no float path yet (its f64 build is not shown to agree with the exact one to 1e-12): build it without --float";

/// The refusal of `line_congruence_strips`' `reguli` type by the float path (the
/// library's reguli strips divide out exact common factors: exact scalars only).
pub const REGULI_REFUSED: &str = "the float path does not build the `reguli` congruence (its strips divide out exact common factors over Q): build it without --float";

/// The refusal of `pn_planar` with a non-constant `denominator` by the float path.
pub const RATIONAL_F_REFUSED: &str = "the float path does not build a rational F (a non-constant `denominator`): the exact op cancels common factors of the curve over Q, which f64 does not find (another representation of higher degree); build it without --float";

/// The name of the value that says which arithmetic built an object.
pub const ARITHMETIC: &str = "arithmetic";

/// A float builder: the op's construction in `f64`.
pub type FloatBuildFn = fn(&OpArgs) -> Result<Vec<Object>, OpError>;

/// One op's float path.
#[derive(Debug, Clone, Copy)]
pub struct FloatOp {
    /// The op (`OpSpec::name`).
    pub name: &'static str,
    /// Builds the objects in `f64`.
    pub build: FloatBuildFn,
    /// What differs from the exact op, if anything (one line, for the docs).
    pub note: &'static str,
}

/// Every op with a float path, in registry order.
pub const FLOAT_OPS: &[FloatOp] = &[
    FloatOp {
        name: "circle_arc",
        build: ops::kernel::build_circle_arc::<f64>,
        note: "",
    },
    FloatOp {
        name: "circle",
        build: ops::kernel::build_circle::<f64>,
        note: "",
    },
    FloatOp {
        name: "cylinder_patch",
        build: ops::kernel::build_cylinder_patch::<f64>,
        note: "",
    },
    FloatOp {
        name: "bezier_curve",
        build: ops::kernel::build_bezier_curve::<f64>,
        note: "weights of mixed sign are refused (the exact op proves pole-freeness by exact bisection)",
    },
    FloatOp {
        name: "degree_elevate",
        build: ops::kernel::build_degree_elevate::<f64>,
        note: "weights of mixed sign are refused",
    },
    FloatOp {
        name: "subdivide",
        build: ops::kernel::build_subdivide::<f64>,
        note: "weights of mixed sign are refused",
    },
    FloatOp {
        name: "bezier_patch",
        build: ops::kernel::build_bezier_patch::<f64>,
        note: "weights of mixed sign are refused",
    },
    FloatOp {
        name: "quadric_curve_image",
        build: ops::quadric::build_curve_image::<f64>,
        note: "the quadric's rational point is found exactly (exact-only algebra), the image is built in f64",
    },
    FloatOp {
        name: "quadric_patch_image",
        build: ops::quadric::build_patch_image::<f64>,
        note: "the quadric's rational point is found exactly (exact-only algebra), the image is built in f64",
    },
    FloatOp {
        name: "sphere_cover",
        build: ops::quadric::build_sphere_cover::<f64>,
        note: "",
    },
    // session 15, floatgeo: line geometry, canal blends, sphere families, conic surfaces,
    // n-dimensional ops, RRMF sweeps, quadric interpolation
    FloatOp {
        name: "line_through_points",
        build: ops::canal::build_line_through_points::<f64>,
        note: "",
    },
    FloatOp {
        name: "line_of_planes",
        build: ops::canal::build_line_of_planes::<f64>,
        note: "",
    },
    FloatOp {
        name: "regulus",
        build: ops::canal::build_regulus::<f64>,
        note: "",
    },
    FloatOp {
        name: "torus",
        build: ops::canal::build_torus::<f64>,
        note: "",
    },
    FloatOp {
        name: "dupin_canal",
        build: ops::canal::build_dupin_canal::<f64>,
        note: "",
    },
    FloatOp {
        name: "dupin_cyclide",
        build: ops::cyclide::build_dupin_cyclide::<f64>,
        note: "",
    },
    FloatOp {
        name: "dupin_cyclide_spheres",
        build: ops::cyclide::build_spheres::<f64>,
        note: "the pe conic through the three cycles and its two families of spheres are built exactly from the exact input (with its exact-only decisions: the type of the conic, whether norm ratios are squares over Q, the rational point of a conic) and rounded once to f64 (formed in f64 the conjugate conic loses the digits its Gram matrix cancels, up to 6 of them); the surface, its patches and every certificate are computed in f64",
    },
    FloatOp {
        name: "cyclide_blend",
        build: ops::cyclide::build_blend::<f64>,
        note: "",
    },
    FloatOp {
        name: "dupin_cyclide_parabolic",
        build: ops::cyclide::build_parabolic::<f64>,
        note: "",
    },
    FloatOp {
        name: "pn_graph",
        build: ops::pn::build_graph::<f64>,
        note: "regularity is decided by f64 Bernstein signs",
    },
    FloatOp {
        name: "pn_support",
        build: ops::pn::build_support::<f64>,
        note: "regularity is decided by f64 Bernstein signs",
    },
    FloatOp {
        name: "pn_revolution",
        build: ops::pn::build_revolution::<f64>,
        note: "regularity is decided by f64 Bernstein signs",
    },
    // --- PN and line-congruence ops (session 15, floatpn) ---
    FloatOp {
        name: "pn_anticaustic",
        build: ops::pn::build_anticaustic::<f64>,
        note: "regularity is decided by f64 Bernstein signs",
    },
    FloatOp {
        name: "pn_planar",
        build: ops::pn::build_planar::<f64>,
        note: "polynomial F only (a non-constant `denominator` is refused: common factors cancelled over Q are not found in f64); regularity is decided by f64 Bernstein signs",
    },
    FloatOp {
        name: "line_congruence_strips",
        build: ops::line_congruence::build_strips::<f64>,
        note: "the `reguli` type is refused (its strips divide out exact common factors over Q: exact scalars only)",
    },
    // --- end of the PN and line-congruence ops ---
    // --- session 16, floatsph: sphere families, conic surfaces, line congruences ---
    FloatOp {
        name: "sphere_family_envelope",
        build: ops::sphere_family::build_envelope::<DoubleDouble>,
        note: "built in double-double (about 106 bits; the result rounded once to f64): the common polynomial factors the construction divides out (gcds and trial divisions over Q) and its exact zero coefficients are decided on the exact input and replayed (rcagd::envelope::Reductions); the certificates are checked in double-double",
    },
    FloatOp {
        name: "sphere_family_cyclographic",
        build: ops::sphere_family::build_cyclographic::<DoubleDouble>,
        note: "built in double-double (about 106 bits; the result rounded once to f64) after the exact op, whose decisions it replays: the contact points are rational, the other sheet's common factors, and the order of the two contact points of a sphere; the second point of h ∩ Ω is formed without cancellation (c₁ = ⟨a,b⟩ + sign(⟨a,b⟩)√disc and ⟨a,a⟩·b − c₁·a); the contact certificates are checked in double-double",
    },
    FloatOp {
        name: "cyclographic_plane_image",
        build: ops::sphere_family::build_plane_image::<f64>,
        note: "the type of the 2-plane is decided on the exact input (an f64 build whose tolerance decides another type is refused); the image planes are f64 values (real square roots)",
    },
    // --- end of session 16, floatsph ---
    FloatOp {
        name: "ph_curve",
        build: ops::ph::build_ph_curve::<f64>,
        note: "the curve only: the display objects (`frame`, `comb`, `feed`) are refused; `arc_length` is an f64 value",
    },
    FloatOp {
        name: "ph_helix",
        build: ops::ph::build_ph_helix::<f64>,
        note: "the curve only: the display objects (`frame`, `comb`, `feed`) are refused; `arc_length` is an f64 value",
    },
    FloatOp {
        name: "ph_hermite",
        build: ops::ph::build_ph_hermite_f64,
        note: "the elimination quartic formed exactly over Q(|d_s||d_f|) from the data and rounded once (formed in f64 it loses up to 8 digits to cancellation), roots by Sturm sequences in f64, interpolants ranked by their f64 bending energy, f64 certificates (the exact op encloses every interpolant from its exact root over Q(|d_s||d_f|))",
    },
    FloatOp {
        name: "ph_planar_curve",
        build: ops::ph_planar::build_curve::<f64>,
        note: "`arc_length` is an f64 value",
    },
    FloatOp {
        name: "ph_planar_offset",
        build: ops::ph_planar::build_offset::<f64>,
        note: "a preimage with a zero on [0, 1] (offset weights not all positive) is refused",
    },
    FloatOp {
        name: "ph_planar_hermite",
        build: ops::ph_planar::build_hermite::<f64>,
        note: "the four interpolants in f64 with tolerance certificates (the exact op rounds an f64 solution to rationals and certifies the rounded curves exactly when a square root is irrational)",
    },
    FloatOp {
        name: "ph_planar_spline",
        build: ops::ph_planar::build_spline::<f64>,
        note: "",
    },
    // session 15, floatgeo: n-dimensional ops
    FloatOp {
        name: "pn_hypersurface",
        build: ops::ndim::build_hypersurface::<f64>,
        note: "the 3-D picture's pole-freeness (X₀ on the domain) is decided by f64 Bernstein signs; the `homogeneous_map` value holds the exact binary values of the f64 coefficients",
    },
    // --- session 17, floatfix ---
    FloatOp {
        name: "anticaustic_nd",
        build: ops::ndim::build_anticaustic::<f64>,
        note: "the 3-D picture's pole-freeness (X₀ on the domain) is decided by f64 Bernstein signs; the `homogeneous_map` value holds the exact binary values of the f64 coefficients",
    },
    // --- end of session 17, floatfix ---
    // --- session 16, floatrest: quadric, canal-blend, n-dim and RRMF ops ---
    FloatOp {
        name: "ph_rrmf",
        build: ops::sweep::build_ph_rrmf::<f64>,
        note: "the frame's exact-only decisions (the rotation polynomial w by Rothstein–Trager residues over Q(i), the common factor cancelled by a gcd over Q) are taken on the exact input (rcagd::ph::rrmf::RationalRmf::along) and the frame is computed in f64 with them; `hermite` data: the exact op's rounded interpolant, converted to f64",
    },
    FloatOp {
        name: "sweep_rrmf",
        build: ops::sweep::build_sweep_rrmf::<f64>,
        note: "the frame's exact-only decisions (the rotation polynomial w, the common factor cancelled over Q) are taken on the exact input and the frame and sweep are computed in f64; the regularity ρκ < 1 is decided exactly on the exact binary values of the f64 curve",
    },
    FloatOp {
        name: "canal_surface_normal_field",
        build: ops::canal::build_canal_normal_field::<f64>,
        note: "the unit field |N|² ≡ d² and ⟨N, ṁ⟩ + d ṙ ≡ 0 are checked to 10⁻⁹ of the largest coefficient in f64 (exactly over Q)",
    },
    FloatOp {
        name: "quadric_miquel_patch",
        build: ops::quadric::build_miquel_patch::<f64>,
        note: "the bilinear preimage is the exact op's (the Miquel chain: its fibre bases are chosen by zero tests over Q and fix the scale of every bilinear corner; the closure and Miquel tests; the choice among the 8 sign flips by exact weight signs), as the quadric's rational point is; its biquadratic image and the certificates are built in f64",
    },
    // --- end of session 16, floatrest ---
    // --- session 17, floatnew: the last five ops "not yet written" ---
    FloatOp {
        name: "sphere_family_recognize",
        build: ops::sphere_family::build_recognized::<DoubleDouble>,
        note: "built in double-double (about 106 bits; the result rounded once to f64): the recognition is a query of the exact input (the span of the normal lines, the pencil of complexes, its discriminant zero or a square over Q, the support functions) and is decided exactly; the envelope of the recovered net is built along the exact build's reductions (rcagd::envelope::Recognition::in_scalar), and its certificates (the normal lines in both complexes, the family is the given one, the envelope's own) are checked in double-double; the `at` contacts: their rationality (the exact op refuses Q(√d)) is decided exactly, the points and their certificates are computed in double-double",
    },
    FloatOp {
        name: "common_transversals",
        build: ops::canal::build_common_transversals::<DoubleDouble>,
        note: "built in double-double (about 106 bits; the result rounded once to f64): the decisions are taken on the exact lines and replayed (rcagd::lines::common_transversals_along): the pivot columns of the 4 × 6 system (its kernel basis), the number of transversals (the discriminant's sign), the root formula, their rationality (the exact op's refusal of Q(√d)) and the farthest pair of meeting points; the transversals, segments and certificates are computed in double-double",
    },
    FloatOp {
        name: "quadric_interpolate",
        build: ops::quadric::build_interpolate::<f64>,
        note: "the exact-only decisions are taken on the exact data and replayed (rcagd::quadric::interpolate_hermite_along): the quadric's rational point, the lowest preimage degree, the fibre bases of the data points (δ chooses its formula by an exact zero test; a tangent datum's fibre position refers to that basis), the pivot columns of the interpolation system (its kernel basis), the admissible member of the solution space and the export split into pieces with weights of one sign; the linear system, its kernel, the member's image and the certificates are computed in f64 (the lowest-degree certificate by the f64 solve of degree n − 1; `tangent_senses` by f64 signs)",
    },
    // --- end of session 17, floatnew ---
];

/// Ops (or whole topics) without a float path, and why; an op listed by name takes
/// precedence over its topic. Ops in neither have no float builder yet.
pub const NO_FLOAT_PATH: &[(&str, &str)] = &[
    // --- PN and line-congruence ops (session 15, floatpn; each tried on its example and
    // gallery objects with a generic builder, `float_pn::survey`) ---
    ("pn_model", "tried and withdrawn (session 15): a cyclide piece whose last Bernstein row vanishes exactly is exported in bidegree (3, 2) over Q and (3, 3) in f64 (the gallery's pn_modeled_patch: 2 of 48 pieces), so the f64 build is another representation"),
    ("pn_loft", "tried and withdrawn (session 15): as pn_model, pieces whose last Bernstein rows vanish exactly are degree-reduced over Q and not in f64 (random draw: the torus R = 4, r = 1, latitudes a = 0 and −1 over den 2, samples = 2: 1 piece of bidegree (3, 2) and 2 of (2, 2) exactly, all (3, 3) in f64)"),
    ("pn_developable", "tried and withdrawn (session 15): the f64 build of the example is another parametrization of the rulings (same degrees, control points 1.25 apart relative to their size): the exact construction normalizes the plane coordinates and the ruling direction by exact gcds and contents over Q, which f64 does not reproduce; pn_developable_edge has a float path"),
    ("pn_developable_motion", "tried and withdrawn (session 15): the exact construction cancels common polynomial factors of the moved planes (gcds over Q: exact-only algebra); in f64 they are not found and the example's envelope has bidegree (30, 4) instead of (8, 4)"),
    ("pn_two_sheet_hyperboloid", "tried and withdrawn (session 15): common polynomial factors of the point and normal are cancelled over Q (exact-only algebra); in f64 they are not found and the example has bidegree (12, 4) instead of (8, 4)"),
    ("pn_laguerre", "tried and withdrawn (session 15): common polynomial factors of the image are cancelled over Q (exact-only algebra); in f64 they are not found and the example (a boosted cyclide) has bidegree (6, 6) instead of (2, 2)"),
    ("pn_cone_motion", "tried and withdrawn (session 15): the f64 regularity check (Bernstein signs of x_u × x_v) reports a singular point at the corner (1/4, 1/4) of the example's domain, which the exact signs exclude; besides, the splitting |m₁ − m₂|² − (r₁ − r₂)² = p₁² + p₂² is decided inside the library in the scalar, on rounded coefficients in f64"),
    ("pn_ruled", "tried and withdrawn (session 15; the splitting p₁² + p₂² = |g|² decided on the exact input, the envelope built in f64): the random draw directrix = [[0, 0], [0, 16/11], [-7/3, -15/7]], ruling = [[1/3, -35/3], [-13/3, 0], [0, 0]] differs from the exact build by 7.8e-10 relative (the 1e-12 of issue 20 not met; cause not analyzed)"),
    ("pn_canal", "tried and withdrawn (session 15; the splitting p₁² + p₂² = |m′|² − r′² decided on the exact input, the envelope built in f64): the PN assembly cancels the gcd of the point and normal polynomials over Q only (a no-op in f64), and for the random draw spine = [[0, -1, 10], [0, 0, 4], [0, 0, 0]], radius = [1], domain = [3/4, 1, 0, 1/4] the f64 patch keeps the factor (a higher bidegree; in another draw (4, 3) instead of (4, 2)) and its points differ from the exact ones by 2.6e-8 relative at the corner (3/4, 0)"),
    ("pn_developable_edge", "tried and withdrawn (session 15): the edge of an offset comes out of degree 9 in f64 and 7 over Q for curve = [[0, 8, 0, 0], [-2, 0, 0, -1], [0, 0, 0, -8/7]], distance -16/3 (common factors cancelled over Q are not found in f64)"),
    ("pn_cone_envelope", "exact-only algebra: the degree-reducing frame of §4.5.1 is searched over Q and the splitting |m₁ − m₂|² − (r₁ − r₂)² = p₁² + p₂² (a sum of two squares over Q) is decided inside the library, which takes no exact frame or splitting for an f64 construction"),
    ("pn_ruled_cyclographic", "exact-only algebra: ⟨g, g⟩ = p₁² + p₂² (a sum of two squares over Q) is decided inside the library's construction, which takes no exact splitting; in f64 it would be decided on the rounded coefficients"),
    ("pn_quadric", "the library's construction is exact (the double cover of the rulings and the splitting are decided over Q) and only converts the finished surface to the scalar: an f64 build would be the exact construction with f64 offsets, not a float path"),
    ("hypercyclide", "as pn_quadric: the library builds the hypercyclide exactly (sums of two squares over Q) and only converts the finished surface to the scalar"),

    // --- end of the PN and line-congruence ops ---
    // --- session 16, floatrest: ops without a float path, and why ---
    ("canal_blend_spheres", "exact-only algebra: the blend surface is rcagd::canal::canal_surface_pole_free over Q, a search over the Gaussian factorizations of |ṁ|² − ṙ² (its splittings as sums of two squares over Q), frames and methods that keeps the first pole-free and smallest build — the search of `canal_surface` (no float path); the library's CanalSurface takes no recorded splitting, frame and method to replay in f64 (canal/envelope.rs, canal/frame.rs), and blend_spheres_f64 splits from f64 complex roots: another parametrization"),
    ("canal_blend_sphere_plane", "exact-only algebra: a Möbius inversion of a sphere–sphere blend whose |ṁ|² − ṙ² must split as a sum of two squares over Q (the same search as `canal_blend_spheres`, refused when it needs Q(√d)); blend_sphere_plane_f64 splits from f64 complex roots, another parametrization"),
    ("ruled_manifold_offset", "exact-only algebra: the unit normal of Theorem 5.2 comes from square tests of |v_a|², |v_b|² over Q(t) and a polynomial point of the conic X² + ΔY² − αZ² = 0 over Q(t) (rcagd_algebra::conic_point, Prop. 5.1), decided inside RuledManifold::offset on the coefficients converted to Q: in f64 they would be decided on rounded coefficients (a square over Q is no square after rounding); a float path needs the exact (λ_a, λ_b, w) passed to the f64 construction, which the library does not take yet"),
    // --- end of session 16, floatrest ---
    // --- session 16, floatsph: sphere families, conic surfaces, line congruences ---
    ("conic_surface", "exact-only library (rcagd::conic_surface is over Q only, Poly<Q>/MPoly<Q>): the rational curve on the surface is a polynomial point of the conic family over Q[t] found by the exact conic-point engine (factorization, square residues, or the proof that none exists over Q), and the parametrization is built from it by exact polynomial algebra; an f64 build would be the exact construction converted at the end, not a float path"),
    ("cone_envelope", "exact-only library (rcagd::conic_surface::cones is over Q only): the generator of the envelope is a polynomial point of a conic family over Q[t] from the exact conic-point engine"),
    ("canal_via_cones", "exact-only library (rcagd::conic_surface::cones is over Q only): the circumscribed cones' envelope takes its generator from the exact conic-point engine over Q[t]"),
    ("type_c_envelope", "exact-only library (rcagd::conic_surface::cones is over Q only): the vertex is the rank-2 member of the pencil λC + μĊ (an exact rank decision) and the generator a polynomial point from the exact conic-point engine"),
    ("quadric_family", "exact-only library (rcagd::conic_surface::quadric_family is over Q only): the polynomial point f(t) on every quadric comes from a plane section solved by the exact conic-point engine over Q[t] (or its named obstruction)"),
    ("canal_hypersurface", "exact-only library (rcagd::conic_surface::mobius is over Q only): the characteristic spheres are parametrized by §5.1 from a polynomial point found by the exact conic-point engine over Q[t]"),
    // --- end of session 16, floatsph ---
    // --- session 17, floatnew: the two of the last five ops without a float path ---
    ("line_congruence_parametrized", "not written (session 17): the library's ParametrizedCongruence is built from polynomial maps over Q only (the op reads MPoly<Q>, the normal congruence of a surface and its strips are formed exactly) and its order and class are exact eliminations with a counted-roots certificate (OrderClass::certificate: proved lower bounds reaching the Bézout bound); a float path needs the congruence instantiated in f64 with those exact values and their certificate as decisions on the exact input (an exact certificate on an f64 object, which the float tests do not allow: every certificate of a float object is inexact), and the focal sheets' rationality (a square discriminant over Q) replayed; line_congruence_strips has a float path for the other congruence types"),
    // --- end of session 17, floatnew ---
    ("ph_dph_septic", "exact-only algebra: exact real roots of the z-polynomial"),
    ("ph_spatial_hermite", "exact-only algebra: the branches live in quadratic fields"),
    ("pipe", "exact-only algebra: the op searches the splittings of |m′|² as sums of two squares over Q (Gaussian factorizations, every frame and method) and keeps the smallest with positive weights; an f64 pipe (`rcagd::canal::pipe_around_ph::<f64>`) would be a different parametrization, so it is not offered as the same construction"),
    ("pipe_ph", "exact-only algebra: as `pipe`, a search over exact splittings of |m′|² = σ² and their Gaussian factors"),
    ("canal_surface", "exact-only algebra: |ṁ|² − ṙ² must split as a sum of two squares over Q"),
    ("canal_chain", "exact-only algebra: each piece is a `canal_surface` (its |ṁ|² − ṙ² must split as a sum of two squares over Q, a search over Gaussian factorizations, frames and methods), and the joints (the same sphere, tangent direction and r·dr/dσ) and the chain's global check are exact decisions"),
    ("hypercone_envelope", "tried and withdrawn (session 15): with the sum of two squares found exactly and the envelope built in f64, the offsets' 3-D pictures have a higher bidegree in f64 than exactly (e.g. (6, 13) against (4, 5)): the exact construction cancels a common factor that is not exactly common in f64"),
    ("pn_ellipsoid", "tried and withdrawn (session 12): the library's EllipsoidPn runs in f64, but its f64 regularity check (Bernstein signs of x_u × x_v) finds a singular point at the corner (1/4, 0) of the example's domain that the exact signs exclude"),
    ("conic_point", "exact-only algebra: a rational point of a conic over Q"),
    ("cyclographic_surface", "exact-only algebra: the sheets are square roots of a polynomial Δ taken exactly (and Δ made a square by a rational point of a quadric)"),
    ("cyclographic_section", "exact-only algebra: as `cyclographic_surface`, square roots of polynomials"),
    ("pn_focal_surface", "exact-only algebra: the principal radii are roots of a quadratic whose discriminant must be a square polynomial over Q"),
    ("analysis", "exact analysis of a PH curve (factorization, exact roots): queries, not constructions"),
    ("quadric_query", "queries of exact algebra (rational points, fibres, collineations over Q)"),
    ("laguerre_query", "queries of exact algebra (Laguerre models over Q)"),
];

/// The plain `f64` instantiations of the ops whose float path runs in double-double
/// ([`DoubleDouble`]; docs/plans/float.md, "Session 18, ddfloat"): not offered by `rcagd
/// build --float` (their results are off by up to 1.8e-9 on random inputs, the
/// cancellations double-double covers); kept so that tests and timings can show what
/// double-double buys and costs.
pub const F64_INSTANCES: &[FloatOp] = &[
    FloatOp {
        name: "sphere_family_envelope",
        build: ops::sphere_family::build_envelope::<f64>,
        note: "",
    },
    FloatOp {
        name: "sphere_family_recognize",
        build: ops::sphere_family::build_recognized::<f64>,
        note: "",
    },
    FloatOp {
        name: "common_transversals",
        build: ops::canal::build_common_transversals::<f64>,
        note: "",
    },
];

/// The float path of the op called `name`.
pub fn find(name: &str) -> Option<&'static FloatOp> {
    FLOAT_OPS.iter().find(|f| f.name == name)
}

/// `true` if the op called `name` has a float path.
pub fn has_float_path(name: &str) -> bool {
    find(name).is_some()
}

/// The names of the ops with a float path, comma-separated (for messages).
pub fn float_op_names() -> String {
    FLOAT_OPS
        .iter()
        .map(|f| f.name)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The exact binary value of a finite `f64` (a non-finite one is an error: the
/// construction overflowed).
fn exact(x: f64) -> Result<Rational, OpError> {
    Rational::try_from(x).map_err(|_| {
        OpError::new(format!(
            "the f64 construction produced the non-finite value {x} (overflow or an ill-conditioned input); build it without --float"
        ))
    })
}

fn check_finite(coords: &[f64]) -> Result<(), OpError> {
    match coords.iter().find(|x| !x.is_finite()) {
        Some(x) => exact(*x).map(|_| ()),
        None => Ok(()),
    }
}

/// An `f64` curve with its exact binary control points.
pub fn exact_curve(c: &BezierCurve<f64>) -> Result<BezierCurve<Rational>, OpError> {
    check_finite(c.coords())?;
    Ok(c.map_scalar(|x| Rational::try_from(*x).unwrap_or_else(|_| Rational::zero())))
}

/// An `f64` patch with its exact binary control points.
pub fn exact_patch(p: &BezierPatch<f64>) -> Result<BezierPatch<Rational>, OpError> {
    check_finite(p.coords())?;
    Ok(p.map_scalar(|x| Rational::try_from(*x).unwrap_or_else(|_| Rational::zero())))
}

/// A curve of an inexact scalar (double-double) rounded once to `f64`, with the exact
/// binary values of those `f64`s as control points.
pub fn rounded_curve<T: rcagd_algebra::Scalar>(
    c: &BezierCurve<T>,
) -> Result<BezierCurve<Rational>, OpError> {
    exact_curve(&c.map_scalar(|x| x.to_f64()))
}

/// A patch of an inexact scalar rounded once to `f64` (as [`rounded_curve`]).
pub fn rounded_patch<T: rcagd_algebra::Scalar>(
    p: &BezierPatch<T>,
) -> Result<BezierPatch<Rational>, OpError> {
    exact_patch(&p.map_scalar(|x| x.to_f64()))
}

/// Marks an object as built in `f64` (the value [`ARITHMETIC`]).
pub fn mark(mut o: Object) -> Object {
    o.values.retain(|v| v.name != ARITHMETIC);
    o.values.insert(
        0,
        NamedQuantity::new(
            ARITHMETIC,
            "built in f64 (`rcagd build --float`): the control points are the exact binary values of f64 results and the certificates are tolerance checks (exact = false), not proofs",
            Quantity::Text("f64".into()),
        ),
    );
    o
}

/// The topic of an op (its registry module), if registered.
fn topic_of(name: &str) -> Option<&'static str> {
    crate::ops::TOPICS
        .iter()
        .find(|(_, ops)| ops.iter().any(|o| o.name == name))
        .map(|(t, _)| *t)
}

/// Why the op called `name` has no float path (`None` if it has one).
pub fn no_float_reason(name: &str) -> Option<&'static str> {
    if has_float_path(name) {
        return None;
    }
    let by_op = NO_FLOAT_PATH.iter().find(|(k, _)| *k == name);
    let by_topic = topic_of(name).and_then(|t| NO_FLOAT_PATH.iter().find(|(k, _)| *k == t));
    Some(by_op.or(by_topic).map_or(
        "not yet written (the construction may have an f64 instantiation; no float builder wraps it yet)",
        |(_, r)| *r,
    ))
}

/// One line for `rcagd ops NAME`: whether the op has a float path, and what differs.
pub fn describe(name: &str) -> String {
    match (find(name), no_float_reason(name)) {
        (Some(op), _) if op.note.is_empty() => {
            "float path (`rcagd build --float`): yes".to_string()
        }
        (Some(op), _) => format!("float path (`rcagd build --float`): yes — {}", op.note),
        (None, Some(why)) => format!("float path (`rcagd build --float`): none — {why}"),
        (None, None) => "float path (`rcagd build --float`): none".to_string(),
    }
}

/// [`describe`] as a Markdown sentence for docs/recipes.md.
pub fn describe_markdown(name: &str) -> String {
    match (find(name), no_float_reason(name)) {
        (Some(op), _) if op.note.is_empty() => {
            "Float path (`rcagd build --float`): yes.".to_string()
        }
        (Some(op), _) => format!("Float path (`rcagd build --float`): yes; {}.", op.note),
        (None, Some(why)) => format!("Float path (`rcagd build --float`): none; {why}."),
        (None, None) => "Float path (`rcagd build --float`): none.".to_string(),
    }
}
