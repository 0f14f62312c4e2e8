/* The vector kernels of the rain flow sweep, written once over a small set of
 * vector operations and instantiated for AVX2 (bake_rain_flow_avx2.c, four
 * texels per vector) and AVX-512 (bake_rain_flow_avx512.c, eight). Each lane
 * does what texel_flux and texel_gather in bake_rain_flow.c do, in the same
 * order, so the bits are the same. What makes that hold:
 * - add, sub, mul, div and the double <-> float conversions are IEEE
 *   operations rounded to nearest in both, each written as its own
 *   intrinsic, and the including files are built with -ffp-contract=off;
 * - V_MAX(a, b) and V_MIN(a, b) (maxpd, minpd) are exactly a > b ? a : b and
 *   a < b ? a : b, the portable code's comparisons;
 * - where the portable code skips a term (a direction without a level drop,
 *   a neighbour that does not send) the lane computes +0 or is masked to +0,
 *   and adding +0 to a sum that is >= +0 changes no bit;
 * - lanes the portable code leaves early (uncovered, dry, facing down) are
 *   computed with the rest and then replaced by what it writes.
 *
 * The includer defines, for L lanes of doubles: V (vector), F (L floats), M
 * (lane mask), I (L 64-bit integers), SIMD_FN(name) (the exported names) and
 * the operations used below. Private to those two files. */

/* The outflows of texels x .. x + L - 1 of row y (texel_flux); i is y w + x. */
static inline void flux_lanes(const flow_job *j, float *const o[8], double *out, const ptrdiff_t step[8], size_t i,
                              int x)
{
    const soak_rain_flow_grid *g = j->g;
    const V zero = V_ZERO();
    V h = V_LOAD(j->depth + i), mobile = V_SUB(h, V_LOAD(g->retain + i));
    M wet = M_AND(M_NONZERO(g->covered + i), M_GT(mobile, zero));
    if (!M_ANY(wet)) { /* nothing moves (dry or uncovered): the common case, cheaply */
        for (int d = 0; d < 8; ++d) F_STORE(o[d] + x, F_ZERO());
        V_STORE(out + x, zero);
        return;
    }
    V drip = V_LOADF(g->drip + i), lvl = V_LOAD(j->lvl + i), diff[9], sum = zero, mx = zero;
    M down = M_AND(wet, M_LT(drip, zero));
    if (all_ones(g->adj + i)) { /* all eight adjacent in every lane (inside a chart) */
        for (int d = 0; d < 8; ++d) diff[d] = V_MAX(V_SUB(lvl, V_LOAD(j->lvl + (ptrdiff_t)i + step[d])), zero);
    } else {
        I adj = I_BYTES(g->adj + i);
        for (int d = 0; d < 8; ++d)
            diff[d] = V_KEEP(V_MAX(V_SUB(lvl, V_LOAD(j->lvl + (ptrdiff_t)i + step[d])), zero), M_BIT(adj, d));
    }
    diff[8] = V_KEEP(V_ADD(h, drip), M_GT(drip, zero));
    for (int d = 0; d < 9; ++d) {
        sum = V_ADD(sum, diff[d]);
        mx = V_MAX(diff[d], mx);
    }
    M active = M_ANDNOT(down, M_AND(wet, M_GT(sum, zero)));
    V moved = V_MIN(V_MUL(V_SET1(0.5), mx), mobile), total = zero;
    for (int d = 0; d < 9; ++d) {
        F od = F_ZERO();
        if (M_ANY(M_AND(active, M_GT(diff[d], zero)))) /* else every lane sends +0 */
            od = F_FROM_V(V_KEEP(V_DIV(V_MUL(moved, diff[d]), sum), active));
        if (d < 8) F_STORE(o[d] + x, od);
        total = V_ADD(total, V_FROM_F(od));
    }
    V_STORE(out + x, V_SELECT(down, V_FROM_F(F_FROM_V(mobile)), total));
}

int SIMD_FN(soak_rain_flux_row)(const flow_job *j, const flux_row_ptrs *row, int y, int x0)
{
    float *o[8];
    ptrdiff_t step[8];
    for (int d = 0; d < 8; ++d) o[d] = row->o[d], step[d] = j->step[d];
    int x = x0, w = j->g->w;
    for (; x + L <= w; x += L) flux_lanes(j, o, row->out, step, (size_t)y * w + x, x);
    if (x < w && w - L >= x0) { /* the rest as a vector that overlaps the last one: same values written again */
        flux_lanes(j, o, row->out, step, (size_t)y * w + (w - L), w - L);
        x = w;
    }
    return x;
}

/* The new depths of texels x .. x + L - 1 of row y (texel_gather). */
static inline void gather_lanes(const flow_job *j, const float *const from[8], const float *const area[8],
                                const double *out, size_t i, int x)
{
    static const int DX[8] = {1, 1, 0, -1, -1, -1, 0, 1};
    const soak_rain_flow_grid *g = j->g;
    const V zero = V_ZERO();
    M covered = M_NONZERO(g->covered + i);
    V depth = V_LOAD(j->depth + i);
    if (!M_ANY(covered)) {
        V_STORE(j->next + i, depth);
        V_STORE(j->lvl_next + i, zero);
        return;
    }
    V vol_in = zero;
    if (all_ones(j->pulls + i)) { /* all eight send in every lane: no masks */
        for (int d = 0; d < 8; ++d) {
            int kx = x + DX[d];
            vol_in = V_ADD(vol_in, V_MUL(V_LOADF(from[d] + kx), V_LOADF(area[d] + kx)));
        }
    } else {
        I pulls = I_BYTES(j->pulls + i);
        for (int d = 0; d < 8; ++d) {
            M pulled = M_BIT(pulls, d);
            if (!M_ANY(pulled)) continue;
            int kx = x + DX[d];
            vol_in = V_ADD(vol_in, V_KEEP(V_MUL(V_LOADF(from[d] + kx), V_LOADF(area[d] + kx)), pulled));
        }
    }
    V h = V_ADD(V_SUB(depth, V_LOAD(out + x)), V_DIV(vol_in, V_LOADF(g->area + i)));
    V next = V_MAX(h, zero);
    V_STORE(j->next + i, V_SELECT(covered, next, depth));
    V_STORE(j->lvl_next + i, V_KEEP(V_ADD(V_LOAD(g->level + i), next), covered));
}

int SIMD_FN(soak_rain_gather_row)(const flow_job *j, const flux_row_ptrs fr[3], const float *const ar[3], int y,
                                  int x0)
{
    static const int DY[8] = {0, -1, -1, -1, 0, 1, 1, 1};
    const float *from[8], *area[8]; /* what neighbour d sends this way, and its row of areas */
    for (int d = 0; d < 8; ++d) {
        from[d] = fr[DY[d] + 1].o[(d + 4) & 7];
        area[d] = ar[DY[d] + 1];
    }
    int x = x0, w = j->g->w;
    for (; x + L + 1 <= w; x += L) gather_lanes(j, from, area, fr[1].out, (size_t)y * w + x, x); /* reads x - 1 .. x + L */
    if (x < w - 1 && w - 1 - L >= x0) { /* as in the flux: a last vector overlapping the one before */
        gather_lanes(j, from, area, fr[1].out, (size_t)y * w + (w - 1 - L), w - 1 - L);
        x = w - 1;
    }
    return x;
}
