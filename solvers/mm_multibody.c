/* mm_multibody.c — the double pendulum, the two-link arm and the
 * slider-crank (see mm_multibody.h for the models and conventions). */
#include "mm_multibody.h"

#include <math.h>
#include <string.h>

/* ==== the double pendulum =================================================== */

int mm_dpend_rhs_lagrange(double t, const double *y, double *dy, void *params)
{
    (void)t;
    const mm_dpend *s = params;
    double d = y[0] - y[1], sd = sin(d), cd = cos(d), w1 = y[2], w2 = y[3];
    double M = s->m1 + s->m2;
    /* Lagrange's equations, divided by l1 and by m2 l2:
     *   M l1 w1' + m2 l2 cos d w2' = -m2 l2 sin d w2^2 - M g sin theta1
     *   l1 cos d w1' + l2 w2'     =  l1 sin d w1^2 - g sin theta2 */
    double r1 = -s->m2 * s->l2 * sd * w2 * w2 - M * s->g * sin(y[0]);
    double r2 = s->l1 * sd * w1 * w1 - s->g * sin(y[1]);
    double det = s->l1 * s->l2 * (s->m1 + s->m2 * sd * sd);  /* M l1 l2 - m2 l1 l2 cos^2 d */
    dy[0] = w1;
    dy[1] = w2;
    dy[2] = (s->l2 * r1 - s->m2 * s->l2 * cd * r2) / det;
    dy[3] = (M * s->l1 * r2 - s->l1 * cd * r1) / det;
    return 0;
}

int mm_dpend_rhs_hamilton(double t, const double *y, double *dy, void *params)
{
    (void)t;
    const mm_dpend *s = params;
    double l1 = s->l1, l2 = s->l2, m2 = s->m2, M = s->m1 + s->m2;
    double d = y[0] - y[1], sd = sin(d), cd = cos(d), p1 = y[2], p2 = y[3];
    double D = s->m1 + m2 * sd * sd;
    /* H = (l2^2 m2 p1^2 + l1^2 M p2^2 - 2 m2 l1 l2 p1 p2 cos d) / (2 l1^2 l2^2 m2 D) + V */
    double C1 = p1 * p2 * sd / (l1 * l2 * D);
    double C2 = (l2 * l2 * m2 * p1 * p1 + l1 * l1 * M * p2 * p2 - 2 * l1 * l2 * m2 * p1 * p2 * cd) *
                sin(2 * d) / (2 * l1 * l1 * l2 * l2 * D * D);
    dy[0] = (l2 * p1 - l1 * p2 * cd) / (l1 * l1 * l2 * D);
    dy[1] = (l1 * M * p2 - l2 * m2 * p1 * cd) / (l1 * l2 * l2 * m2 * D);
    dy[2] = -M * s->g * l1 * sin(y[0]) - C1 + C2;
    dy[3] = -m2 * s->g * l2 * sin(y[1]) + C1 - C2;
    return 0;
}

void mm_dpend_to_momenta(const mm_dpend *s, const double *yw, double *yp)
{
    double c = cos(yw[0] - yw[1]), M = s->m1 + s->m2, w1 = yw[2], w2 = yw[3];
    yp[0] = yw[0];
    yp[1] = yw[1];
    yp[2] = M * s->l1 * s->l1 * w1 + s->m2 * s->l1 * s->l2 * c * w2;
    yp[3] = s->m2 * s->l2 * s->l2 * w2 + s->m2 * s->l1 * s->l2 * c * w1;
}

void mm_dpend_to_velocities(const mm_dpend *s, const double *yp, double *yw)
{
    double dy[4];
    mm_dpend_rhs_hamilton(0, yp, dy, (void *)s);
    yw[0] = yp[0];
    yw[1] = yp[1];
    yw[2] = dy[0];
    yw[3] = dy[1];
}

double mm_dpend_energy(const mm_dpend *s, const double *yw, double *scale)
{
    double M = s->m1 + s->m2, w1 = yw[2], w2 = yw[3];
    double t1 = 0.5 * M * s->l1 * s->l1 * w1 * w1, t2 = 0.5 * s->m2 * s->l2 * s->l2 * w2 * w2;
    double t3 = s->m2 * s->l1 * s->l2 * w1 * w2 * cos(yw[0] - yw[1]);
    double v1 = -M * s->g * s->l1 * cos(yw[0]), v2 = -s->m2 * s->g * s->l2 * cos(yw[1]);
    if (scale)
        *scale = fabs(t1) + fabs(t2) + fabs(t3) + M * s->g * s->l1 + s->m2 * s->g * s->l2;
    return t1 + t2 + t3 + v1 + v2;
}

void mm_dpend_linear(const mm_dpend *s, double *w_slow, double *w_fast)
{
    /* det(K - w^2 M0) = a w^4 - b w^2 + c = 0 with M0 = M(0), K = diag(M g l1, m2 g l2) */
    double M = s->m1 + s->m2, l1 = s->l1, l2 = s->l2, g = s->g;
    double a = s->m1 * s->m2 * l1 * l1 * l2 * l2;
    double b = M * s->m2 * g * l1 * l2 * (l1 + l2);
    double c = M * s->m2 * g * g * l1 * l2;
    /* b^2 - 4ac = (M m2 g l1 l2)^2 ((l1 + l2)^2 - 4 m1 l1 l2 / M) > 0: a sum of squares form */
    double e = M * s->m2 * g * l1 * l2;
    double disc = e * sqrt((l1 - l2) * (l1 - l2) + 4 * s->m2 * l1 * l2 / M);
    double big = (b + disc) / (2 * a);
    *w_fast = sqrt(big);
    *w_slow = sqrt(c / (a * big));       /* product of the roots is c/a: no cancellation */
}

void mm_dpend_points(const mm_dpend *s, double theta1, double theta2, double *x1, double *y1,
                     double *x2, double *y2)
{
    *x1 = s->l1 * sin(theta1);
    *y1 = -s->l1 * cos(theta1);
    *x2 = *x1 + s->l2 * sin(theta2);
    *y2 = *y1 - s->l2 * cos(theta2);
}

/* ==== the two-link robot arm ================================================= */

void mm_robot2_mass(const mm_robot2 *s, double q2, double *M)
{
    double l1 = s->l1, l2 = s->l2, c = cos(q2);
    M[0] = s->m1 * l1 * l1 / 3 + s->m2 * (l1 * l1 + l2 * l2 / 3 + l1 * l2 * c);
    M[1] = M[2] = s->m2 * (l2 * l2 / 3 + 0.5 * l1 * l2 * c);
    M[3] = s->m2 * l2 * l2 / 3;
}

/* c(q, q') + G(q): everything but M q'' */
static void robot_bias(const mm_robot2 *s, const double *q, const double *qd, double *h)
{
    double hh = 0.5 * s->m2 * s->l1 * s->l2 * sin(q[1]);
    double c12 = cos(q[0] + q[1]);
    h[0] = -hh * (2 * qd[0] * qd[1] + qd[1] * qd[1]) + (0.5 * s->m1 + s->m2) * s->g * s->l1 * cos(q[0]) +
           0.5 * s->m2 * s->g * s->l2 * c12;
    h[1] = hh * qd[0] * qd[0] + 0.5 * s->m2 * s->g * s->l2 * c12;
}

void mm_robot2_inverse(const mm_robot2 *s, const double *q, const double *qd, const double *qdd,
                       double *tau)
{
    double M[4], h[2];
    mm_robot2_mass(s, q[1], M);
    robot_bias(s, q, qd, h);
    tau[0] = M[0] * qdd[0] + M[1] * qdd[1] + h[0];
    tau[1] = M[2] * qdd[0] + M[3] * qdd[1] + h[1];
}

void mm_robot2_forward(const mm_robot2 *s, const double *q, const double *qd, const double *tau,
                       double *qdd)
{
    double M[4], h[2], c = cos(q[1]);
    mm_robot2_mass(s, q[1], M);
    robot_bias(s, q, qd, h);
    /* det M in the form that is visibly positive (no cancellation) */
    double det = s->m2 * s->l1 * s->l1 * s->l2 * s->l2 * (s->m1 / 9 + s->m2 * (1.0 / 3 - 0.25 * c * c));
    double r0 = tau[0] - h[0], r1 = tau[1] - h[1];
    qdd[0] = (M[3] * r0 - M[1] * r1) / det;
    qdd[1] = (M[0] * r1 - M[2] * r0) / det;
}

void mm_robot2_energy(const mm_robot2 *s, const double *q, const double *qd, double *T, double *V)
{
    double M[4];
    mm_robot2_mass(s, q[1], M);
    *T = 0.5 * (M[0] * qd[0] * qd[0] + 2 * M[1] * qd[0] * qd[1] + M[3] * qd[1] * qd[1]);
    *V = s->g * ((0.5 * s->m1 + s->m2) * s->l1 * sin(q[0]) + 0.5 * s->m2 * s->l2 * sin(q[0] + q[1]));
}

void mm_robot2_points(const mm_robot2 *s, const double *q, double *x, double *y)
{
    x[0] = y[0] = 0;
    x[1] = s->l1 * cos(q[0]);
    y[1] = s->l1 * sin(q[0]);
    x[2] = x[1] + s->l2 * cos(q[0] + q[1]);
    y[2] = y[1] + s->l2 * sin(q[0] + q[1]);
}

/* ==== the slider-crank ======================================================= */

/* Phi_q, 4 x 5 row-major, over (phi1, x2, y2, phi2, x3) */
static void sc_jacobian(const mm_sc_model *s, const double *q, double *J)
{
    double r = s->r, h = 0.5 * s->l, s1 = sin(q[0]), c1 = cos(q[0]), s2 = sin(q[3]), c2 = cos(q[3]);
    const double rows[MM_SC_NC][MM_SC_NQ] = {
        {r * s1, 1, 0, h * s2, 0},
        {-r * c1, 0, 1, -h * c2, 0},
        {0, 1, 0, -h * s2, -1},
        {0, 0, 1, h * c2, 0},
    };
    for (int i = 0; i < MM_SC_NC; i++)
        for (int j = 0; j < MM_SC_NQ; j++)
            J[i * MM_SC_NQ + j] = rows[i][j];
}

void mm_sc_constraints(const mm_sc_model *s, const double *q, const double *qd, double *Phi,
                       double *Phid)
{
    double h = 0.5 * s->l;
    if (Phi) {
        Phi[0] = q[1] - h * cos(q[3]) - s->r * cos(q[0]);
        Phi[1] = q[2] - h * sin(q[3]) - s->r * sin(q[0]);
        Phi[2] = q[1] + h * cos(q[3]) - q[4];
        Phi[3] = q[2] + h * sin(q[3]);
    }
    if (Phid) {
        double J[MM_SC_NC * MM_SC_NQ];
        sc_jacobian(s, q, J);
        for (int i = 0; i < MM_SC_NC; i++) {
            Phid[i] = 0;
            for (int j = 0; j < MM_SC_NQ; j++)
                Phid[i] += J[i * MM_SC_NQ + j] * qd[j];
        }
    }
}

void mm_sc_assemble(const mm_sc_model *s, double phi1, double w, double *q, double *qd)
{
    double r = s->r, l = s->l, s1 = sin(phi1), c1 = cos(phi1);
    double sn2 = -r * s1 / l, c2 = sqrt((1 - sn2) * (1 + sn2));   /* the rod leans back to the axis */
    double w2 = -r * c1 * w / (l * c2);                           /* from y_B = 0 differentiated */
    q[0] = phi1;
    q[3] = atan2(sn2, c2);
    q[1] = r * c1 + 0.5 * l * c2;
    q[2] = r * s1 + 0.5 * l * sn2;
    q[4] = r * c1 + l * c2;
    qd[0] = w;
    qd[3] = w2;
    qd[1] = -r * s1 * w - 0.5 * l * sn2 * w2;
    qd[2] = r * c1 * w + 0.5 * l * c2 * w2;
    qd[4] = -r * s1 * w - l * sn2 * w2;
}

/* Solve the n x n system A x = b (row-major, overwritten) by Gaussian
 * elimination with partial pivoting; -1 if a pivot is 0. */
static int gauss(int n, double *A, double *b)
{
    for (int k = 0; k < n; k++) {
        int p = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[p * n + k]))
                p = i;
        if (A[p * n + k] == 0)
            return -1;
        if (p != k) {
            for (int j = 0; j < n; j++) {
                double t = A[k * n + j];
                A[k * n + j] = A[p * n + j];
                A[p * n + j] = t;
            }
            double t = b[k];
            b[k] = b[p];
            b[p] = t;
        }
        for (int i = k + 1; i < n; i++) {
            double f = A[i * n + k] / A[k * n + k];
            for (int j = k; j < n; j++)
                A[i * n + j] -= f * A[k * n + j];
            b[i] -= f * b[k];
        }
    }
    for (int k = n - 1; k >= 0; k--) {
        for (int j = k + 1; j < n; j++)
            b[k] -= A[k * n + j] * b[j];
        b[k] /= A[k * n + k];
    }
    return 0;
}

int mm_sc_accel(const mm_sc_model *s, const double *q, const double *qd, double alpha,
                double beta, double *qdd, double *lambda)
{
    const double Q[MM_SC_NQ] = {s->torque, 0, 0, 0, 0};
    double J[MM_SC_NC * MM_SC_NQ], Phi[MM_SC_NC], Phid[MM_SC_NC];
    sc_jacobian(s, q, J);
    mm_sc_constraints(s, q, qd, Phi, Phid);
    /* gamma = -(Phi_q q')_q q' (the terms of Phi'' without q'') */
    double h = 0.5 * s->l, w1 = qd[0], w2 = qd[3], c1 = cos(q[0]), s1 = sin(q[0]);
    double c2 = cos(q[3]), s2 = sin(q[3]);
    double gam[MM_SC_NC] = {
        -(s->r * c1 * w1 * w1 + h * c2 * w2 * w2),
        -(s->r * s1 * w1 * w1 + h * s2 * w2 * w2),
        h * c2 * w2 * w2,
        h * s2 * w2 * w2,
    };
    /* The null-space form of the same linear system (Nikravesh ch. 13):
     * with the crank angle u = phi1 independent and v = (x2, y2, phi2, x3)
     * dependent, Phi_v v'' = rhs - Phi_u u'' gives q'' = T u'' + C, and
     * T^T (M q'' - Q) = 0 (T spans the null space of Phi_q) gives
     *     u'' = T^T (Q - M C) / (T^T M T);
     * then Phi_v^T lambda = (Q - M q'')_v.  Only Phi_v (lengths, well
     * conditioned while the rod is not vertical) is factored.  The Schur
     * complement Phi_q M^-1 Phi_q^T used before mixed the inverse masses,
     * 1/J_rod next to 1/m_rod: with J_rod = 1e-6, m_rod = 55 its condition
     * was 1e8, the accelerations erred 1e-9 relative, and DOP853 at rtol
     * 1e-13 could not meet its tolerance against that noise (1e6 steps). */
    double Phiv[MM_SC_NC * MM_SC_NC], cv[MM_SC_NC], tv[MM_SC_NC];
    for (int i = 0; i < MM_SC_NC; i++) {
        cv[i] = gam[i] - 2 * alpha * Phid[i] - beta * beta * Phi[i];      /* Baumgarte */
        tv[i] = -J[i * MM_SC_NQ];
        for (int k = 0; k < MM_SC_NC; k++)
            Phiv[i * MM_SC_NC + k] = J[i * MM_SC_NQ + 1 + k];
    }
    double A[MM_SC_NC * MM_SC_NC];
    memcpy(A, Phiv, sizeof A);
    if (gauss(MM_SC_NC, A, cv) != 0)
        return MM_ESINGULAR;
    memcpy(A, Phiv, sizeof A);
    if (gauss(MM_SC_NC, A, tv) != 0)
        return MM_ESINGULAR;
    const double M[MM_SC_NQ] = {s->J_crank, s->m_rod, s->m_rod, s->J_rod, s->m_piston};
    double T[MM_SC_NQ] = {1, tv[0], tv[1], tv[2], tv[3]}, C[MM_SC_NQ] = {0, cv[0], cv[1], cv[2], cv[3]};
    double num = 0, den = 0;
    for (int j = 0; j < MM_SC_NQ; j++) {
        num += T[j] * (Q[j] - M[j] * C[j]);
        den += T[j] * M[j] * T[j];
    }
    double u = num / den;
    for (int j = 0; j < MM_SC_NQ; j++)
        qdd[j] = T[j] * u + C[j];
    if (lambda) {
        double f[MM_SC_NC];
        for (int i = 0; i < MM_SC_NC; i++) {
            f[i] = Q[1 + i] - M[1 + i] * qdd[1 + i];
            for (int k = 0; k < MM_SC_NC; k++)
                A[i * MM_SC_NC + k] = Phiv[k * MM_SC_NC + i];          /* Phi_v^T */
        }
        if (gauss(MM_SC_NC, A, f) != 0)
            return MM_ESINGULAR;
        for (int i = 0; i < MM_SC_NC; i++)
            lambda[i] = f[i];
    }
    return MM_OK;
}

double mm_sc_kinetic(const mm_sc_model *s, const double *q, const double *qd)
{
    (void)q;
    return 0.5 * (s->J_crank * qd[0] * qd[0] + s->m_rod * (qd[1] * qd[1] + qd[2] * qd[2]) +
                  s->J_rod * qd[3] * qd[3] + s->m_piston * qd[4] * qd[4]);
}

double mm_sc_inertia(const mm_sc_model *s, double phi, double *dJ)
{
    /* velocities per unit crank speed, with lam = r/l, C = cos phi2 = sqrt(1 - lam^2 sin^2 phi),
     * u = lam cos phi / C:  phi2' = -u,  x3' = -r sin phi (1 + u),
     * G2' = (-r sin phi (1 + u/2), r cos phi / 2) */
    double r = s->r, lam = r / s->l, sn = sin(phi), cs = cos(phi);
    double C = sqrt((1 - lam * sn) * (1 + lam * sn)), u = lam * cs / C;
    double k2 = -u, v3 = -r * sn * (1 + u), gx = -r * sn * (1 + 0.5 * u), gy = 0.5 * r * cs;
    double J = s->J_crank + s->m_rod * (gx * gx + gy * gy) + s->J_rod * k2 * k2 + s->m_piston * v3 * v3;
    if (dJ) {
        double du = -lam * sn * (C * C - lam * lam * cs * cs) / (C * C * C);
        double dv3 = -r * cs * (1 + u) - r * sn * du;
        double dgx = -r * cs * (1 + 0.5 * u) - 0.5 * r * sn * du, dgy = -0.5 * r * sn;
        *dJ = 2 * (s->m_rod * (gx * dgx + gy * dgy) + s->J_rod * k2 * (-du) + s->m_piston * v3 * dv3);
    }
    return J;
}

int mm_sc_rhs_baumgarte(double t, const double *y, double *dy, void *params)
{
    (void)t;
    const mm_sc_system *p = params;
    for (int j = 0; j < MM_SC_NQ; j++)
        dy[j] = y[MM_SC_NQ + j];
    return mm_sc_accel(&p->sc, y, y + MM_SC_NQ, p->alpha, p->beta, dy + MM_SC_NQ, NULL);
}

int mm_sc_rhs_reduced(double t, const double *y, double *dy, void *params)
{
    (void)t;
    const mm_sc_system *p = params;
    double q[MM_SC_NQ], qd[MM_SC_NQ], qdd[MM_SC_NQ];
    mm_sc_assemble(&p->sc, y[0], y[1], q, qd);
    int rc = mm_sc_accel(&p->sc, q, qd, 0, 0, qdd, NULL);
    dy[0] = y[1];
    dy[1] = qdd[0];
    return rc;
}

/* The energy error one DOP853 step may make at state y (see mm_multibody.h):
 * its local error is held to atol + rtol |y_j| in each component (atol =
 * rtol), and the energy moves by the gradient of E times that, eq. (7):
 *   dE <= sum_j |dE/dy_j| rtol (1 + |y_j|).
 * The unwrapped angles' |y_j| is in it on purpose: DOP853 loosens its hold
 * on an angle that has turned many times, and so does this allowance. */
double mm_dpend_energy_allowance(const mm_dpend *s, const double *y, double rtol)
{
    double M = s->m1 + s->m2, k = s->m2 * s->l1 * s->l2, d = y[0] - y[1], w1 = y[2], w2 = y[3];
    double g[4] = {
        -k * w1 * w2 * sin(d) + M * s->g * s->l1 * sin(y[0]),
        k * w1 * w2 * sin(d) + s->m2 * s->g * s->l2 * sin(y[1]),
        M * s->l1 * s->l1 * w1 + k * w2 * cos(d),
        s->m2 * s->l2 * s->l2 * w2 + k * w1 * cos(d),
    };
    double a = 0;
    for (int j = 0; j < 4; j++)
        a += fabs(g[j]) * rtol * (1 + fabs(y[j]));
    return a;
}

/* The exponential regime of a separation d(t) on the grid x (from 1e3 d0,
 * past the start's transient, to 1e-3, before saturation) and the least
 * squares of ln d = a + lambda t over it; se: the slope's standard error.
 * Returns 0 when there is no regime to fit (then only *i_lo, *i_hi set). */
int mm_growth_fit(const double *x, const double *d, int n, double d0, int *i_lo, int *i_hi, double *lam,
                  double *a0, double *se)
{
    *i_lo = *i_hi = -1;
    for (int i = 0; i < n; i++) {
        if (*i_lo < 0 && d[i] > 1e3 * d0)
            *i_lo = i;
        if (*i_hi < 0 && d[i] > 1e-3)
            *i_hi = i;
    }
    if (*i_lo > 0 && *i_hi < 0)
        *i_hi = n;                                 /* still growing at the end of the window */
    if (!(*i_lo > 0 && *i_hi > *i_lo + 8))
        return 0;
    double st = 0, sl = 0, stt = 0, stl = 0;
    int m = *i_hi - *i_lo;
    for (int i = *i_lo; i < *i_hi; i++) {
        double t = x[i], l = log(d[i]);
        st += t, sl += l, stt += t * t, stl += t * l;
    }
    double den = m * stt - st * st, ss = 0;
    *lam = (m * stl - st * sl) / den, *a0 = (sl - *lam * st) / m;
    for (int i = *i_lo; i < *i_hi; i++) {
        double e = log(d[i]) - *a0 - *lam * x[i];
        ss += e * e;
    }
    *se = sqrt(ss / (m - 2) * m / den);
    return 1;
}

/* ---- chapter 4 (dyn-double-pendulum): Lagrange's equations against Hamilton's ---- */

double mm_dpend_lh_residual(const mm_dpend *s, const double *y, double *scale)
{
    double dl[4], yp[4], dh[4];
    mm_dpend_rhs_lagrange(0, y, dl, (void *)s);
    mm_dpend_to_momenta(s, y, yp);
    mm_dpend_rhs_hamilton(0, yp, dh, (void *)s);
    double d = y[0] - y[1], dd = y[2] - y[3], c = cos(d), sn = sin(d), k = s->m2 * s->l1 * s->l2;
    double M11 = (s->m1 + s->m2) * s->l1 * s->l1, M22 = s->m2 * s->l2 * s->l2;
    double p1 = M11 * dl[2] + k * (c * dl[3] - sn * dd * y[3]);
    double p2 = M22 * dl[3] + k * (c * dl[2] - sn * dd * y[2]);
    double big = fabs(M11 * dl[2]) + fabs(k * dl[3]) + fabs(k * dd * y[3]) + fabs(M22 * dl[3]) +
                 fabs(k * dl[2]) + fabs(k * dd * y[2]) + fabs(dh[2]) + fabs(dh[3]);
    double worst = fmax(fmax(fabs(p1 - dh[2]), fabs(p2 - dh[3])),
                        fmax(fabs(dh[0] - y[2]), fabs(dh[1] - y[3])) * (M11 + M22));
    double cond = (M11 + M22) * (M11 + M22) / (M11 * M22 - k * k * c * c);
    *scale = (big + (fabs(y[2]) + fabs(y[3])) * (M11 + M22)) * cond;
    return worst;
}

/* ---- chapter 4 (dyn-slider-crank): the joint forces against Newton's law ---------- */

double mm_sc_momentum_residual(const mm_sc_model *s, const double *qdd, const double *lam, double *scale)
{
    double fa = hypot(lam[0], lam[1]), fb = hypot(lam[2], lam[3]), N = -lam[3];
    double Fx = -lam[0], Fy = -lam[1] + N;
    double px = s->m_rod * qdd[1] + s->m_piston * qdd[4], py = s->m_rod * qdd[2];
    *scale = fa + fb + fabs(s->m_rod * qdd[1]) + fabs(s->m_piston * qdd[4]) + fabs(s->m_rod * qdd[2]);
    return hypot(Fx - px, Fy - py);
}

double mm_sc_drift(const mm_sc_model *s, const double *q)
{
    double Phi[MM_SC_NC], d = 0;
    mm_sc_constraints(s, q, NULL, Phi, NULL);
    for (int k = 0; k < MM_SC_NC; k++)
        d = fmax(d, fabs(Phi[k]));
    return d;
}
