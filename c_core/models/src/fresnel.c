/* Fresnel reflectance. Dielectric: Born & Wolf, Principles of Optics (7th
 * ed.) sec. 1.5.2, amplitude ratios r_s, r_p averaged for unpolarised light.
 * Conductor: the closed form of the complex-index Fresnel equations used in
 * [Lag13] (Lagarde, v1.3 correction of Weidlich-Wilkie's code); we keep the
 * algebra but guard the 0/0 cases at grazing incidence. */
#include "soak/fresnel.h"

#include <math.h>
#include <stddef.h>

static int eta_ok(double eta) { return soak_in_range(eta, SOAK_ETA_MIN, SOAK_ETA_MAX); }

double soak_fresnel_dielectric_raw(double cos_i, double eta, double *cos_t)
{
    if (eta == 1.0) { /* no interface */
        if (cos_t) *cos_t = cos_i;
        return 0.0;
    }
    double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0) { /* total internal reflection */
        if (cos_t) *cos_t = 0.0;
        return 1.0;
    }
    double ct = sqrt(1.0 - sin2_t);
    if (cos_t) *cos_t = ct;
    double rs = (cos_i - eta * ct) / (cos_i + eta * ct);
    double rp = (eta * cos_i - ct) / (eta * cos_i + ct);
    double R = 0.5 * (rs * rs + rp * rp);
    return R > 1.0 ? 1.0 : R;
}

soak_status soak_fresnel_dielectric(double cos_i, double eta, double *R, double *cos_t)
{
    if (!R) return SOAK_ERR_NULL;
    if (!soak_in_range(cos_i, 0.0, 1.0) || !eta_ok(eta)) return SOAK_ERR_ARG;
    *R = soak_fresnel_dielectric_raw(cos_i, eta, cos_t);
    return SOAK_OK;
}

double soak_fresnel_conductor_raw(double cos_i, double eta, double k)
{
    if (k == 0.0 && eta == 1.0) return 0.0;
    if (cos_i <= 0.0) return 1.0; /* grazing: both polarisations reflect fully */
    double c2 = cos_i * cos_i;
    double s2 = 1.0 - c2;
    double eta2 = eta * eta, k2 = k * k;
    double t0 = eta2 - k2 - s2;
    double a2b2 = sqrt(t0 * t0 + 4.0 * eta2 * k2);
    double t1 = a2b2 + c2;
    double a = sqrt(fmax(0.0, 0.5 * (a2b2 + t0)));
    double t2 = 2.0 * cos_i * a;
    /* t1 + t2 underflows to 0 only when cos_i^2 and the index terms all do
     * (cos_i < ~1e-154 with eta = 1 and k^2 underflowing): the grazing limit. */
    if (!(t1 + t2 > 0.0)) return 1.0;
    double Rs = (t1 - t2) / (t1 + t2);
    double t3 = c2 * a2b2 + s2 * s2;
    double t4 = t2 * s2;
    double Rp = Rs * (t3 - t4) / (t3 + t4);
    double R = 0.5 * (Rs + Rp);
    return R < 0.0 ? 0.0 : (R > 1.0 ? 1.0 : R);
}

soak_status soak_fresnel_conductor(double cos_i, double eta, double k, double *R)
{
    if (!R) return SOAK_ERR_NULL;
    if (!soak_in_range(cos_i, 0.0, 1.0) || !eta_ok(eta) || !soak_in_range(k, 0.0, SOAK_ETA_MAX)) return SOAK_ERR_ARG;
    *R = soak_fresnel_conductor_raw(cos_i, eta, k);
    return SOAK_OK;
}

soak_status soak_fresnel_schlick(double cos_i, double R0, double *R)
{
    if (!R) return SOAK_ERR_NULL;
    if (!soak_in_range(cos_i, 0.0, 1.0) || !soak_in_range(R0, 0.0, 1.0)) return SOAK_ERR_ARG;
    double m = 1.0 - cos_i;
    double m2 = m * m;
    *R = R0 + (1.0 - R0) * m2 * m2 * m;
    return SOAK_OK;
}

soak_status soak_fresnel_r0(double eta, double k, double *R0)
{
    if (!R0) return SOAK_ERR_NULL;
    if (!eta_ok(eta) || !soak_in_range(k, 0.0, SOAK_ETA_MAX)) return SOAK_ERR_ARG;
    double num = (eta - 1.0) * (eta - 1.0) + k * k;
    double den = (eta + 1.0) * (eta + 1.0) + k * k;
    *R0 = num / den;
    return SOAK_OK;
}

/* 20-point Gauss-Legendre nodes/weights on [-1,1] (positive half). */
static const double gl_x[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195, 0.5108670019508271,
                                0.6360536807265150, 0.7463319064601508, 0.8391169718222188, 0.9122344282513258,
                                0.9639719272779138, 0.9931285991850949};
static const double gl_w[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183819, 0.1316886384491765,
                                0.1181945319615182, 0.1019301198172403, 0.0832767415767047, 0.0626720483341094,
                                0.0406014298003862, 0.0176140071391533};

/* 2 * int_a^b R(mu, eta) mu dmu by 20-point Gauss-Legendre. */
static double panel(double a, double b, double eta)
{
    double half = 0.5 * (b - a), mid = 0.5 * (a + b), sum = 0.0;
    for (int i = 0; i < 10; ++i) {
        double d = half * gl_x[i];
        double m1 = mid - d, m2 = mid + d;
        sum += gl_w[i] * (soak_fresnel_dielectric_raw(m1, eta, NULL) * m1 + soak_fresnel_dielectric_raw(m2, eta, NULL) * m2);
    }
    return 2.0 * half * sum;
}

/* The integrand has a square-root feature at mu_lo (grazing transmission for
 * eta > 1, the critical angle for eta < 1) whose width shrinks as eta -> 1,
 * so panels are graded geometrically away from mu_lo. */
static double graded_integral(double mu_lo, double eta)
{
    double span = 1.0 - mu_lo, sum = 0.0, prev = mu_lo;
    for (int e = -12; e <= 0; ++e) {
        double next = e == 0 ? 1.0 : mu_lo + span * pow(10.0, e);
        sum += panel(prev, next, eta);
        prev = next;
    }
    return sum;
}

soak_status soak_fresnel_dielectric_avg(double eta, double *R_avg)
{
    if (!R_avg) return SOAK_ERR_NULL;
    if (!eta_ok(eta)) return SOAK_ERR_ARG;
    if (eta == 1.0) {
        *R_avg = 0.0;
        return SOAK_OK;
    }
    double mu_c = eta < 1.0 ? sqrt(1.0 - eta * eta) : 0.0; /* cos of the critical angle */
    double total = mu_c * mu_c /* TIR part: 2 int_0^mu_c mu dmu */ + graded_integral(mu_c, eta);
    *R_avg = total > 1.0 ? 1.0 : total;
    return SOAK_OK;
}
