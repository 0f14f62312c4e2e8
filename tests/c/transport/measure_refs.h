/* Independent references for the Monte Carlo measurement tests: graded
 * Gauss-Legendre quadrature (nodes from testutil), Chandrasekhar's
 * H-function and an adding-doubling slab solver. Written here, inside the
 * tests, so that nothing in libsoak checks itself. Static functions:
 * included by several test files. */
#ifndef SOAK_TEST_MEASURE_REFS_H
#define SOAK_TEST_MEASURE_REFS_H

#include <math.h>
#include <string.h>

#include "testutil.h"

#define REF_MAXN 256
#define REF_PI 3.14159265358979323846

/* Nodes on (0,1] in geometric panels [0,1e-6], [1e-6,1e-5], ... [0.1,1],
 * resolving the mu log mu behaviour of H near 0. Returns the node count. */
static inline int ref_graded_nodes(int per_panel, double *x, double *w)
{
    int n = 0;
    double lo = 0.0;
    for (int p = 6; p >= 0; --p) {
        double hi = pow(10.0, -p);
        tu_gauss_legendre(per_panel, lo, hi, x + n, w + n);
        n += per_panel;
        lo = hi;
    }
    return n;
}

/* Chandrasekhar's H-function for isotropic scattering with single-scattering
 * albedo omega, from the "1/H" form of its integral equation (Chandrasekhar,
 * Radiative Transfer, 1960, ch. V, eq. 23-24 form):
 *   1/H(mu) = sqrt(1 - omega) + (omega/2) int_0^1 mu' H(mu') / (mu + mu') dmu',
 * iterated to convergence on the graded nodes. Fills H at the nodes and
 * returns the node count. */
typedef struct ref_hfunc {
    int n;
    double x[REF_MAXN], w[REF_MAXN], h[REF_MAXN];
    double omega;
} ref_hfunc;

static inline double ref_h_apply(const ref_hfunc *hf, const double *h, double mu)
{
    double s = 0.0;
    for (int j = 0; j < hf->n; ++j) s += hf->w[j] * hf->x[j] * h[j] / (mu + hf->x[j]);
    return 1.0 / (sqrt(1.0 - hf->omega) + 0.5 * hf->omega * s);
}

static inline int ref_h_solve(ref_hfunc *hf, double omega)
{
    hf->omega = omega;
    hf->n = ref_graded_nodes(24, hf->x, hf->w);
    double next[REF_MAXN];
    for (int i = 0; i < hf->n; ++i) hf->h[i] = 1.0;
    for (int it = 0; it < 100000; ++it) {
        double change = 0.0;
        for (int i = 0; i < hf->n; ++i) {
            /* Damped: at omega = 1 the plain iteration maps a scale c of H
             * to 1/c and oscillates forever; averaging removes that mode. */
            next[i] = 0.5 * (hf->h[i] + ref_h_apply(hf, hf->h, hf->x[i]));
            change = fmax(change, fabs(next[i] - hf->h[i]));
        }
        memcpy(hf->h, next, sizeof(double) * (size_t)hf->n);
        if (change < 1e-14) return 1;
    }
    return 0;
}

/* H at any mu in (0,1] by the Nystrom extension of the converged solution. */
static inline double ref_h_eval(const ref_hfunc *hf, double mu) { return ref_h_apply(hf, hf->h, mu); }

/* Residual of the other standard form, H = 1 + (omega/2) mu H int H/(mu+mu'). */
static inline double ref_h_residual_standard_form(const ref_hfunc *hf, double mu)
{
    double s = 0.0;
    for (int j = 0; j < hf->n; ++j) s += hf->w[j] * hf->h[j] / (mu + hf->x[j]);
    double H = ref_h_eval(hf, mu);
    return H - (1.0 + 0.5 * hf->omega * mu * H * s);
}

/* ---- Adding-doubling, isotropic scattering, index-matched slab --------
 * Discrete radiances at N Gauss nodes mu_i on (0,1]; an operator maps the
 * incident radiance vector to the outgoing one (quadrature weights inside).
 * Thin layer dtau (first order; conserves flux exactly at omega = 1):
 *   R_ij = omega dtau w_j / (2 mu_i),  T_ij = delta_ij (1 - dtau/mu_i) + R_ij;
 * for a collimated beam of flux F = 1 per unit area normal to it, the
 * diffusely reflected and transmitted radiances r0_i = t0_i =
 * omega dtau / (4 pi mu_i) and the direct beam keeps a0 = 1 - dtau/mu0.
 * Doubling two identical (top-bottom symmetric) layers:
 *   U = (I - R R)^-1 (R t0 + a0 r0),  D = t0 + R U,
 *   r0' = r0 + T U,  t0' = T D + a0 t0,  a0' = a0^2,
 *   R' = R + T (I - R R)^-1 R T,  T' = T (I - R R)^-1 T.
 * (van de Hulst, Multiple Light Scattering, 1980, ch. 4; Wiscombe 1976.)
 * Total reflectance = 2 pi sum w_i mu_i U_i / mu0, etc. */
#define REF_AD_N 24

typedef double ref_mat[REF_AD_N][REF_AD_N];

static inline void ref_mat_mul(const ref_mat a, const ref_mat b, ref_mat out)
{
    ref_mat t;
    for (int i = 0; i < REF_AD_N; ++i)
        for (int j = 0; j < REF_AD_N; ++j) {
            double s = 0.0;
            for (int k = 0; k < REF_AD_N; ++k) s += a[i][k] * b[k][j];
            t[i][j] = s;
        }
    memcpy(out, t, sizeof t);
}

static inline void ref_mat_vec(const ref_mat a, const double *v, double *out)
{
    double t[REF_AD_N];
    for (int i = 0; i < REF_AD_N; ++i) {
        double s = 0.0;
        for (int k = 0; k < REF_AD_N; ++k) s += a[i][k] * v[k];
        t[i] = s;
    }
    memcpy(out, t, sizeof t);
}

/* out = (I - M)^-1 B by Gauss-Jordan with partial pivoting; B has nb columns
 * stored as a matrix (nb <= REF_AD_N) or one vector (nb = 1 uses bvec). */
static inline void ref_solve(const ref_mat M, ref_mat B, double *bvec)
{
    double a[REF_AD_N][2 * REF_AD_N + 1];
    for (int i = 0; i < REF_AD_N; ++i) {
        for (int j = 0; j < REF_AD_N; ++j) {
            a[i][j] = (i == j ? 1.0 : 0.0) - M[i][j];
            a[i][REF_AD_N + j] = B ? B[i][j] : 0.0;
        }
        a[i][2 * REF_AD_N] = bvec ? bvec[i] : 0.0;
    }
    for (int c = 0; c < REF_AD_N; ++c) {
        int p = c;
        for (int r = c + 1; r < REF_AD_N; ++r)
            if (fabs(a[r][c]) > fabs(a[p][c])) p = r;
        for (int k = 0; k <= 2 * REF_AD_N; ++k) {
            double t = a[c][k];
            a[c][k] = a[p][k];
            a[p][k] = t;
        }
        double d = a[c][c];
        for (int k = 0; k <= 2 * REF_AD_N; ++k) a[c][k] /= d;
        for (int r = 0; r < REF_AD_N; ++r) {
            if (r == c) continue;
            double f = a[r][c];
            if (f == 0.0) continue;
            for (int k = 0; k <= 2 * REF_AD_N; ++k) a[r][k] -= f * a[c][k];
        }
    }
    for (int i = 0; i < REF_AD_N; ++i) {
        if (B)
            for (int j = 0; j < REF_AD_N; ++j) B[i][j] = a[i][REF_AD_N + j];
        if (bvec) bvec[i] = a[i][2 * REF_AD_N];
    }
}

/* Total reflectance and transmittance (direct beam included) of an
 * index-matched isotropic slab of optical thickness tau, albedo omega, for a
 * collimated beam at cosine mu0. */
static inline void ref_slab_doubling_n(double tau, double omega, double mu0, int doublings, double *R_out,
                                double *T_out)
{
    double x[REF_AD_N], w[REF_AD_N];
    tu_gauss_legendre(REF_AD_N, 0.0, 1.0, x, w);
    double dt = tau / pow(2.0, doublings);
    static ref_mat R, T, RR, tmp, tmp2;
    double r0[REF_AD_N], t0[REF_AD_N], a0 = 1.0 - dt / mu0;
    for (int i = 0; i < REF_AD_N; ++i) {
        for (int j = 0; j < REF_AD_N; ++j) {
            R[i][j] = omega * dt * w[j] / (2.0 * x[i]);
            T[i][j] = (i == j ? 1.0 - dt / x[i] : 0.0) + R[i][j];
        }
        r0[i] = t0[i] = omega * dt / (4.0 * REF_PI * x[i]);
    }
    for (int d = 0; d < doublings; ++d) {
        ref_mat_mul(R, R, RR);
        double U[REF_AD_N], D[REF_AD_N], v[REF_AD_N];
        ref_mat_vec(R, t0, v);
        for (int i = 0; i < REF_AD_N; ++i) U[i] = v[i] + a0 * r0[i];
        ref_solve(RR, NULL, U);
        ref_mat_vec(R, U, v);
        for (int i = 0; i < REF_AD_N; ++i) D[i] = t0[i] + v[i];
        ref_mat_vec(T, U, v);
        for (int i = 0; i < REF_AD_N; ++i) r0[i] += v[i];
        ref_mat_vec(T, D, v);
        for (int i = 0; i < REF_AD_N; ++i) t0[i] = v[i] + a0 * t0[i];
        a0 *= a0;
        /* R' = R + T (I-RR)^-1 R T ; T' = T (I-RR)^-1 T */
        ref_mat_mul(R, T, tmp);
        ref_solve(RR, tmp, NULL);
        ref_mat_mul(T, tmp, tmp);
        memcpy(tmp2, T, sizeof tmp2);
        ref_solve(RR, tmp2, NULL);
        ref_mat_mul(T, tmp2, tmp2);
        for (int i = 0; i < REF_AD_N; ++i)
            for (int j = 0; j < REF_AD_N; ++j) R[i][j] += tmp[i][j];
        memcpy(T, tmp2, sizeof tmp2);
    }
    double Rs = 0.0, Ts = 0.0;
    for (int i = 0; i < REF_AD_N; ++i) {
        Rs += w[i] * x[i] * r0[i];
        Ts += w[i] * x[i] * t0[i];
    }
    *R_out = 2.0 * REF_PI * Rs / mu0;
    *T_out = 2.0 * REF_PI * Ts / mu0 + a0;
}

/* The first-order start leaves an error proportional to dtau; Richardson
 * extrapolation over two starting thicknesses removes it. Each run conserves
 * flux exactly at omega = 1, so the extrapolation does too. */
static inline void ref_slab_doubling(double tau, double omega, double mu0, double *R_out, double *T_out)
{
    double R1, T1, R2, T2;
    ref_slab_doubling_n(tau, omega, mu0, 20, &R1, &T1);
    ref_slab_doubling_n(tau, omega, mu0, 21, &R2, &T2);
    *R_out = 2.0 * R2 - R1;
    *T_out = 2.0 * T2 - T1;
}

#endif
