/* Unchecked forms of the porous model for the library's own loops (inputs
 * already validated), and the Gauss-Legendre rule the models integrate with.
 * Private to the models layer. */
#ifndef SOAK_POROUS_INTERNAL_H
#define SOAK_POROUS_INTERNAL_H

double soak_porous_nb_raw(double sp, double theta_i, double theta_o);
double soak_porous_Ap_raw(double ka, double nb);
/* (1 - A_p) = (1 - k_a)^n_b computed from r = 1 - k_a without cancellation. */
double soak_porous_keep_raw(double r, double nb);
/* n-point Gauss-Legendre nodes and weights on [0,1], 2 <= n <= 64. */
void soak_porous_gauss_legendre_raw(int n, double *x, double *w);


#endif
