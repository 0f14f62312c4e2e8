/* Rain wetting of a mesh, baked into its UV texture.
 *
 * [Hnat06] (Hnat et al. 2006, sec. 3.3.1 and 5) computes a mesh's rain wet
 * map as the light map of an emissive plane above it, then adds drop impacts
 * rendered into a "drops texture". We compute the real quantities instead:
 *
 * 1. Surface sampling. Every triangle is rasterised in UV space (texel
 *    centres, v = 0 at the bottom image row); a texel covered by a triangle
 *    gets that triangle's surface point p, unit normal n (the geometric
 *    normal turned to the side of the interpolated vertex normal) and world
 *    area (triangle area / UV area * texel UV area). Faces without UVs,
 *    degenerate faces, faces outside [0, 1]^2, UDIM tiles and overlapping
 *    UVs follow soak/bake_uv.h (an overlap goes to one face by a rule that
 *    does not depend on the faces' order). Texels outside every triangle stay
 *    empty (value 0, later filled by a `gutter`-texel dilation).
 *
 * 2. Sky exposure (Monte Carlo, Embree occlusion queries through
 *    soak/geometry.h). Rain arrives from directions u (unit, pointing to the
 *    sky) with a density p(u); the flux onto a surface element is
 *    F(n) = integral p(u) V(p, u) max(0, n.u) du (V = 1 when the ray from p
 *    along u escapes the mesh). Exposure is F(n) / F_open, F_open =
 *    integral p(u) (up.u) du the flux onto an open horizontal surface, so an
 *    open upward plane has exposure 1 and a roofed floor 0. Estimator:
 *    E = (1/N) sum V_i max(0, n.u_i) / F_open with u_i ~ p stratified in
 *    cos theta (N = rays per texel, counter-based random numbers of
 *    (seed, texel), so results do not depend on the thread count).
 *      rain sky: p uniform in solid angle over the cone of half-angle
 *        `spread` around `rain_dir`; F_open = rain_dir.up (1 + cos spread)/2
 *        (mean cosine of the cone, times the tilt).
 *      hemisphere sky ([Hnat06]'s emissive sky, = ambient occlusion): u
 *        cosine-distributed about n, E = (1/N) sum V_i; open plane 1.
 *
 * 3. Rain over time, steps of dt = duration / steps:
 *    - drop impacts: a Poisson process; the number of drops landing in a
 *      texel in a step is Poisson(lambda), lambda = rate_drops * E * A * dt,
 *      rate_drops = rainfall / drop volume (drops per horizontal area per
 *      time). Counts are drawn per (seed, step, texel) by inversion
 *      (lambda > 30: normal approximation, rounded, >= 0).
 *    - splat: each drop's volume is spread by a normalised Gaussian kernel of
 *      standard deviation splat_radius (world length, converted to texels at
 *      the mean texel size), added as depth = volume / area;
 *    - evaporation: depth -= evaporation * dt, not below 0;
 *    - downhill flow: water above the film a surface retains
 *      (retention * max(0, n.up)) is mobile and is routed over the surface by
 *      a multiple-flow-direction scheme (Quinn et al. 1991, "The prediction of
 *      hillslope flow paths for distributed hydrological modelling using
 *      digital terrain models", Hydrol. Process. 5): from texel i to each
 *      3D-adjacent neighbour j in proportion to the drop of the water level
 *      s = p.up + depth, at most half the largest level difference per
 *      iteration (so levels never cross: flat puddles form in concave,
 *      upward-facing regions). A texel whose downhill direction leads off
 *      the surface (an open edge) or that faces down (n.up < -1e-6, an
 *      overhang; an exactly vertical face is not one) drains its mobile water
 *      off the mesh (drips). flow_iterations routing sweeps per step.
 *    - puddles (flow_iterations > 0): before the sweeps, the water in each
 *      depression of the surface becomes a horizontal surface no higher
 *      than its spill level, from a priority flood of the levels (Barnes,
 *      Lehman & Mulla 2014, "Priority-Flood", Computers & Geosciences 62,
 *      117-127); what exceeds the depression's capacity goes to its sill
 *      texel and flows on. Volume is conserved.
 *    - falling film (film = 1): a face steeper than flat keeps, besides
 *      the static film retention * max(0, n.up), the film that runs over it
 *      while rain falls. W. Nusselt, "Die Oberflaechenkondensation des
 *      Wasserdampfes", Z. VDI 60 (1916) 541-546 and 569-575; textbook form
 *      in Bird, Stewart & Lightfoot, "Transport Phenomena", 2nd ed. (2002),
 *      sec. 2.2 (flow of a falling film): a laminar film on a plane at angle
 *      theta from the horizontal carrying the volume flow q per unit width
 *      (m^2/s) is  h = (3 mu q / (rho g sin theta))^(1/3)  thick (m; BSL
 *      write it with the mass flow Gamma = rho q and the angle beta = 90 deg
 *      - theta from the vertical, h = (3 mu Gamma / (rho^2 g cos beta))^(1/3))
 *      and its surface moves at u_s = rho g sin theta h^2 / (2 mu) (m/s).
 *      Water at 20 C: mu = 1.002e-3 Pa s, rho = 998.2 kg/m^3; g = 9.80665.
 *      q per texel comes from the steady discharge Q (m^3/s) of the same
 *      routing as the flow (soak_rain_flow_discharge, private): each texel
 *      receives rainfall * E * A, loses evaporation * A, passes the rest
 *      along the surface's steepest descent, drips it off open edges and
 *      down-facing texels, or holds it (pits). The descent is gravity
 *      projected on the surface, -(up - (up.n) n), mapped into texel steps
 *      through the UV Jacobian (least squares on dpdx, dpdy); the water
 *      a texel passes on fills a box within it (the whole texel where rain
 *      falls on it, else the bounding box of what flowed in), moved one
 *      texel along the descent's major axis and split between the two
 *      texels it then overlaps by their share of its width (private
 *      bake_rain_stream.h: a stream keeps its edge; for a full box the
 *      line-crossing form of the D-infinity routing of D. G. Tarboton,
 *      "A new method for the determination of flow directions and upslope
 *      areas in grid digital elevation models", Water Resour. Res. 33(2)
 *      (1997) 309-319, with the direction from the surface's own gradient);
 *      a share crossing an edge that faces down the slope drips, one
 *      crossing an edge along the flow goes to the other texel; level
 *      texels (|g_t| < 1e-6) and targets that are not lower fall back to
 *      the level drops of the sweeps. q = Q / width with width = A * (texel
 *      steps per metre along the descent's larger texel axis): the stream's
 *      width across the flow, exact on a plane along an axis or a diagonal
 *      of the grid and for stretched texels. The
 *      film is kept as the texel's retention (the larger of the two), so
 *      the water of the time loop fills it, the flow passes what exceeds it
 *      on downhill, and mass is conserved. The film moves at u_s, 5-20 mm/s
 *      for films of 20-50 um: across a face within one step, where the
 *      sweeps move water one texel each. So each step, before the sweeps, a
 *      cascade (private soak_rain_flow_cascade, the same shares in the same
 *      order as the discharge) passes the water above the film of every
 *      texel whose film is thicker than its static retention on downhill at
 *      once; it stops in the first texel without such a film (ledges,
 *      floors, puddles), where the sweeps take over (not with
 *      flow_iterations 0: then no water moves). Where flow collects the film
 *      thickens (streaks); below an edge where the water drips it ends.
 *      sin theta = 0 (flat) has no film; a film over SOAK_RAIN_FILM_MAX is
 *      cut there (the laminar form does not hold: a sheet of water whose
 *      depth the level routing resolves).
 *    - runnels (contact_angle_deg > 0): a film whose flux per unit width q
 *      is below the minimum wetting rate cannot keep the face covered and
 *      gathers into rivulets. D. E. Hartley, W. Murgatroyd, "Criteria for
 *      the break-up of thin liquid layers flowing isothermally over solid
 *      surfaces", Int. J. Heat Mass Transfer 7 (1964) 1003-1015, force
 *      criterion: Gamma_min = 1.69 (mu rho / g')^(1/5) (sigma (1 - cos
 *      theta_c))^(3/5) kg/(m s), q_min = Gamma_min / rho, with g' = g sin
 *      theta for a face inclined at theta (their plate is vertical; the
 *      film's driving gravity is g sin theta: our extension). Spacing: the
 *      fingering wavelength of a film front, 14 l, l = h (3 Ca)^(-1/3) =
 *      (h l_c^2 / sin theta)^(1/3), l_c = sqrt(sigma / (rho g)) (S. M.
 *      Troian, E. Herbolzheimer, S. A. Safran, J. F. Joanny, "Fingering
 *      instabilities of driven spreading films", Europhys. Lett. 10 (1989)
 *      25-30), of the median broken film (one spacing per bake: straight
 *      streaks). Each rivulet carries the flux of its spacing, Q = q
 *      spacing (water conserved across every line), with the thin-rivulet
 *      profile h(y) = theta_c (a^2 - y^2) / (2 a) and the lubrication flux
 *      Q = 4 g sin theta theta_c^3 a^4 / (105 nu) (Nusselt's local flux
 *      g sin theta h^3 / (3 nu) integrated over the profile; the narrow
 *      rivulet of B. R. Duffy, H. K. Moffatt, "Flow of a viscous trickle on
 *      a slowly varying incline", Chem. Eng. J. 60 (1995) 141-146). Rivulet k runs
 *      along s = (k + phase) spacing, s the position across the slope,
 *      p . unit(up x n); the phase puts the rivulets on the relief's
 *      grooves (arg of the sum over broken texels of kappa e^(2 pi i s /
 *      spacing), kappa = -dn_s/ds the across-slope concavity), from the
 *      seed where no texel is concave (a plane); a texel's film is the
 *      rivulets' mean depth over its width across the flow. Where 2 a >=
 *      spacing the rivulets touch and the film holds. Water, sigma = 0.0728
 *      N/m. The retention of the time loop follows the rivulets.
 * 4. Output wetness w = 1 - exp(-depth / saturation_depth) in [0,1], and
 *    w = 1 wherever a film runs (film >= SOAK_RAIN_FILM_RUNNING): the film
 *    is supplied continuously, so the pores under it are full and it covers
 *    the texel (the wetness chain, soak/wetness.h step 2: pore fill 1, film
 *    coverage 1); without this a running 30 um film read as w = 0.14 at the
 *    default saturation 0.2 mm, and walls in rain looked dry. The exposure,
 *    the water depth and the film thickness are available too.
 * 5. Frame sequences (soak_rain_frames_*): the same surface, exposure,
 *    routing and film, in time, with the mean rain (rainfall * E * area per
 *    texel; the drops' spots are `soak bake drops`). Per step of dt =
 *    duration / steps (the last step before a frame's time t cut short at
 *    t, so the state at t never depends on which other frames are made):
 *    - the film as a kinematic wave (M. J. Lighthill & G. B. Whitham, "On
 *      kinematic waves I", Proc. R. Soc. A 229 (1955) 281-316): on the
 *      film's faces (where the steady film of step 3b exceeds the static
 *      retention) the depth h obeys continuity with Nusselt's discharge
 *      per unit width q = K h^3, K = rho g sin theta / (3 mu) (the mean
 *      velocity q / h = K h^2 is 2/3 of the surface velocity u_s of step 3b).
 *      Discretised on the routing graph: texels highest first, each one
 *      implicit (backward Euler) step, area h' + dt sqrt(A) K h'^3 = area h
 *      + dt (rain + inflow), what leaves passed on in the routing's shares
 *      (soak_rain_flow_shares) within the same step; stable at any dt, mass
 *      conserving, and its steady state is step 3b's film exactly. On a
 *      plane under rain r from t = 0 its solution is the rising limb of
 *      D. A. Woolhiser & J. A. Liggett, "Unsteady one-dimensional flow over
 *      a plane - the rising hydrograph", Water Resour. Res. 3 (1967) 753:
 *      h = min(r t, h_steady(x)); the point where the two meet (the film's
 *      front, behind it the steady film) is at x = K r^2 t^3, moving at the
 *      kinematic celerity dq/dh = 3 K h^2 = 2 u_s. A front running onto a
 *      dry face (a sheltered wall fed from a ledge) moves at the shock
 *      speed q / h = (2/3) u_s (continuity). After the rain the film
 *      drains: along the characteristics h is constant and x grows by 3 K
 *      h^2 (t - duration), so long after the rain h -> sqrt(nu x / (g sin
 *      theta (t - duration))) (H. Jeffreys, "The draining of a vertical
 *      plate", Proc. Camb. Phil. Soc. 26 (1930) 204-205; nu = mu / rho).
 *    - step 3's puddle filling, then its sweeps, level the water of every
 *      other texel (puddles, flats, gentle slopes), not the film's faces;
 *    - evaporation, during and after the rain, as in step 3.
 *    Wetness as in step 4 with the film the water on the film's faces
 *    (film >= SOAK_RAIN_FILM_RUNNING: w = 1); once the film has drained
 *    thinner, w = 1 - exp(-depth / saturation) and evaporation dries it.
 *    Runnels (contact_angle_deg > 0): step 3c's lattice, placed once on the
 *    steady film, gathers each frame's film on the film's faces (its flux
 *    K h^3 against q_min) into rivulets carrying that frame's flux; the
 *    wave itself runs on the mean film (its balance is the mean film's).
 *
 * Lengths are in the mesh's unit (metres assumed for the rainfall rates);
 * times in seconds. */
#ifndef SOAK_BAKE_RAIN_H
#define SOAK_BAKE_RAIN_H

#include <stdint.h>

#include "soak/bake.h"
#include "soak/bake_uv.h"
#include "soak/geometry.h"
#include "soak/image.h"
#include "soak/status.h"
#include "soak/vec.h"

typedef enum soak_rain_sky {
    SOAK_RAIN_SKY_RAIN = 0,   /* cone of rain directions (default) */
    SOAK_RAIN_SKY_HEMISPHERE  /* cosine-weighted hemisphere about n (ambient occlusion) */
} soak_rain_sky;

/* Limits of soak_rain_params (soak_rain_check). */
#define SOAK_RAIN_MAX_RAYS 65536
#define SOAK_RAIN_MAX_SPREAD 89      /* degrees */
#define SOAK_RAIN_MAX_DURATION 1e7   /* s */
#define SOAK_RAIN_MAX_STEPS 100000   /* time steps, flow iterations */
#define SOAK_RAIN_MAX_RATE 1000      /* rainfall, evaporation, mm/h */
#define SOAK_RAIN_MAX_DROP 0.01      /* drop diameter, m */
#define SOAK_RAIN_MAX_SPLAT 1        /* m */
#define SOAK_RAIN_MAX_RETENTION 0.1  /* m */
#define SOAK_RAIN_MAX_SATURATION 1   /* m */
#define SOAK_RAIN_MAX_GUTTER 64      /* texels */

/* Water at 20 C and standard gravity for the falling film (step 3b):
 * viscosity (Pa s) and density (kg/m^3) from the CRC Handbook of Chemistry
 * and Physics; thickest film kept, m. */
#define SOAK_RAIN_WATER_VISCOSITY 1.002e-3
#define SOAK_RAIN_WATER_DENSITY 998.2
#define SOAK_RAIN_GRAVITY 9.80665
#define SOAK_RAIN_FILM_MAX 1e-3
/* A film at least this thick (m) runs and covers its texel (step 4): a
 * micrometre, well above the half-float resolution of the film maps near
 * 10 um and far below the 10-50 um of films in rain. */
#define SOAK_RAIN_FILM_RUNNING 1e-6
/* n.up below -this is an overhang (drips); float normals round n.up of a
 * vertical face to ~1e-7. */
#define SOAK_RAIN_OVERHANG_TOL 1e-6

typedef struct soak_rain_params {
    uint64_t seed;
    int rays;               /* rays per texel, 1..65536 */
    soak_rain_sky sky;
    soak_vec3 up;           /* world up (unit after normalisation; non-zero) */
    soak_vec3 rain_dir;     /* mean direction the rain comes from (toward the sky), rain_dir.up > 0 */
    double spread_deg;      /* cone half-angle, [0, 89] */
    double duration;        /* s, [0, 1e7]; 0 = exposure only, no water */
    int steps;              /* 1..100000 */
    double rainfall_mm_h;   /* [0, 1000] mm/h of water on a horizontal surface */
    double drop_diameter;   /* m, (0, 0.01] */
    double splat_radius;    /* m, [0, 1]; 0 = drop stays in its texel */
    double evaporation_mm_h;/* [0, 1000] */
    double retention;       /* film depth kept on a flat surface, m, [0, 0.1] */
    double saturation_depth;/* depth for w = 1 - 1/e, m, (0, 1] */
    int flow_iterations;    /* routing sweeps per step, 0..100000 */
    int gutter;             /* texels of dilation into empty texels, 0..64 */
    int film;               /* 1: falling film on slopes (step 3b), 0: static retention only */
    soak_uv_options uv;     /* step 1's UV rules (soak/bake_uv.h): wrap outside [0,1]^2, no UDIM */
    double contact_angle_deg; /* [0, 90]: > 0 breaks thin films into runnels (step 3c); 0 = the film holds */
} soak_rain_params;

/* seed 0, 64 rays, rain sky, up +z, rain from +z, spread 10 deg, 600 s in
 * 32 steps, 10 mm/h, 2 mm drops, splat 2 mm, evaporation 0.5 mm/h,
 * retention 0.2 mm, saturation 0.2 mm, 16 flow iterations, gutter 4,
 * falling film on, contact angle 0 (no runnels). */
void soak_rain_defaults(soak_rain_params *p);
soak_status soak_rain_check(const soak_rain_params *p);

/* Where the steady rain of step 3b goes, m^3/s: what falls on the mesh
 * (rainfall * sum E A), what drips off open edges and down-facing faces,
 * what collects in pits and on flats (puddles), what evaporates on the way
 * (in = dripped + held + evaporated). All 0 with film = 0 or no rain. */
typedef struct soak_rain_runoff {
    double in, dripped, held, evaporated;
} soak_rain_runoff;

typedef struct soak_rain_result {
    soak_image wetness;  /* 1 channel, [0,1] */
    soak_image exposure; /* 1 channel, >= 0 (1 = open horizontal surface) */
    soak_image water;    /* 1 channel, water depth, m */
    soak_image coverage; /* 1 channel, 1 where a triangle covers the texel centre */
    soak_image film;     /* 1 channel, falling film thickness while rain falls, m (0 with film = 0) */
    soak_rain_runoff runoff;
    soak_uv_stats uv;    /* what step 1 made of the faces (soak/bake_uv.h) */
    int runnel_texels;   /* step 3c: texels whose film broke into rivulets */
    double runnel_spacing; /* step 3c: the rivulets' spacing, m (0 where none) */
} soak_rain_result;

/* Bakes at width x height (soak_bake_check_size). The mesh must have UVs
 * (SOAK_ERR_ARG with "mesh has no UVs" in err otherwise) and at least one
 * triangle. The geometry used for occlusion is built from the mesh inside.
 * On SOAK_OK every image of out is allocated (free with
 * soak_rain_result_free); on error nothing is. */
soak_status soak_bake_rain(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                           const soak_bake_exec *exec, soak_rain_result *out, char *err, size_t errlen);
void soak_rain_result_free(soak_rain_result *r);

/* Nusselt's laminar film (step 3b): thickness (m) of a film carrying q
 * (m^2/s) down a plane at sin_theta, at most SOAK_RAIN_FILM_MAX; 0 for
 * q <= 0, sin_theta <= 0 or NaN (sin_theta > 1 counts as 1). */
double soak_rain_film_thickness(double q, double sin_theta);
/* Its surface velocity (m/s) for thickness h in (0, SOAK_RAIN_FILM_MAX];
 * 0 otherwise. */
double soak_rain_film_surface_speed(double h, double sin_theta);

/* Step 4's wetness of water depth `depth` under a film `film` (m). */
double soak_rain_wetness(double depth, double film, double saturation_depth);

/* ---- step 5: frame sequences ---- */

/* Limits of the frames: the latest time (s) and the most time steps a
 * frame may need. */
#define SOAK_RAIN_MAX_FRAME_TIME 1e7
#define SOAK_RAIN_MAX_FRAME_STEPS 10000000L

/* Volumes (m^3) since t = 0: the rain that fell on the mesh, what dripped
 * off it, what is on it now, what evaporated (in = dripped + held +
 * evaporated up to rounding). */
typedef struct soak_rain_balance {
    double in, dripped, held, evaporated;
} soak_rain_balance;

typedef struct soak_rain_frame {
    soak_image wetness; /* 1 channel, [0,1] (step 4) */
    soak_image water;   /* 1 channel, water depth, m */
    soak_image film;    /* 1 channel, film on the film's faces, m (at most SOAK_RAIN_FILM_MAX) */
    soak_rain_balance balance;
} soak_rain_frame;

typedef struct soak_rain_frames soak_rain_frames;

/* Surface, exposure and film of mesh (as soak_bake_rain, same errors);
 * p->duration must be > 0 (SOAK_ERR_ARG otherwise) and p->film 1 for a
 * film in time (with 0 every texel is left to the sweeps). */
soak_status soak_rain_frames_create(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                                    const soak_bake_exec *exec, soak_rain_frames **out, char *err, size_t errlen);
void soak_rain_frames_destroy(soak_rain_frames *f);
/* The state at time t (s, [0, SOAK_RAIN_MAX_FRAME_TIME]; rain during [0,
 * duration]) into out (allocated; free with soak_rain_frame_free). The
 * same t gives the same bits whatever was asked before and at any thread
 * count; asking in increasing t reuses the steps done. */
soak_status soak_rain_frames_at(soak_rain_frames *f, double t, const soak_bake_exec *exec, soak_rain_frame *out,
                                char *err, size_t errlen);
void soak_rain_frame_free(soak_rain_frame *r);
/* The sky exposure of the frames' mesh (step 2, gutter not applied). */
const soak_image *soak_rain_frames_exposure(const soak_rain_frames *f);
/* Step 3c's lattice of a sequence (placed on the steady film, as the single
 * map's): texels of the steady film that broke, and the spacing (m; 0: no
 * runnels). */
void soak_rain_frames_runnels(const soak_rain_frames *f, int *texels, double *spacing);
/* What step 1 made of the mesh's faces. */
const soak_uv_stats *soak_rain_frames_uv(const soak_rain_frames *f);

#endif
