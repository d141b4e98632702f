/* Drive a MoorDyn-C input of scripts/moordyn/write_input.py through the surge of flexmoor's
 * cases/ocean/oc4-semi-surge.yaml (and oc3-hywind-surge.yaml): every Coupled point (the
 * fairleads) moves by s(t) = A r(t) sin(2 pi t / T) in x, with flexmoor's default ramp r, the
 * quintic smoothstep 10 x^3 - 15 x^4 + 6 x^5 of x = t / T (one period; r = 1 after it).
 *
 * MoorDyn moves a coupled point linearly over a coupling step h from the position and velocity
 * it is given; the driver gives x(t) and the chord's velocity (x(t + h) - x(t)) / h, so the
 * fairleads are exactly on the surge at every step's end. After each step it takes each
 * fairlead's force from MoorDyn (the coupled point's net force: its line's end node, the top
 * segment's tension and damping plus the half segment's weight, drag and seabed force) less the
 * end node's mass matrix (with added mass) times the surge's acceleration: the lumped-mass form
 * of flexmoor's end_tension (the end element's nodal force balance, inertia included). Also kept:
 * MoorDyn's FairTen (|T + Td| of the top segment). Extremes over t >= FROM of records every
 * SAMPLE seconds (flexmoor's output interval) and the CPU of MoorDyn_Init and of the steps.
 *
 * Usage: surge_driver LINES.txt DURATION H [AMPLITUDE PERIOD FROM SAMPLE RAMP] [SERIES.csv]
 *   defaults 2.0 m, 10 s, 100 s, 0.1 s, RAMP = PERIOD (0: no ramp).
 * Build (against an installed MoorDyn-C, include dir .../include/moordyn):
 *   cc -O2 -o surge_driver surge_driver.c -I$MD/include/moordyn -L$MD/lib -lmoordyn -lm
 */
#include <MoorDyn2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define MAX_POINTS 16

static double amplitude = 2.0, period = 10.0, ramp = 10.0;

/* The surge s(t) and its first two derivatives. */
static void surge(double t, double* s, double* v, double* a) {
  const double w = 2.0 * M_PI / period;
  double r = 1.0, dr = 0.0, ddr = 0.0;
  if (ramp > 0.0 && t < ramp) {
    const double x = t / ramp;
    r = x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
    dr = 30.0 * x * x * (1.0 - x) * (1.0 - x) / ramp;
    ddr = 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (ramp * ramp);
  }
  const double sn = amplitude * sin(w * t), cs = amplitude * w * cos(w * t);
  *s = r * sn;
  *v = dr * sn + r * cs;
  *a = ddr * sn + 2.0 * dr * cs - r * w * w * sn;
}

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

int main(int argc, char** argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: %s LINES.txt DURATION H [A T FROM SAMPLE RAMP] [SERIES.csv]\n",
            argv[0]);
    return 2;
  }
  const double duration = atof(argv[2]), h = atof(argv[3]);
  double from = 100.0, sample = 0.1;
  if (argc > 4) amplitude = atof(argv[4]);
  if (argc > 5) period = atof(argv[5]);
  ramp = period;
  if (argc > 6) from = atof(argv[6]);
  if (argc > 7) sample = atof(argv[7]);
  if (argc > 8) ramp = atof(argv[8]);
  FILE* series = argc > 9 ? fopen(argv[9], "w") : NULL;

  MoorDyn md = MoorDyn_Create(argv[1]);
  if (!md) return 1;
  MoorDyn_SetVerbosity(md, MOORDYN_WRN_LEVEL);
  unsigned int ndof = 0, npoints = 0, nlines = 0;
  MoorDyn_NCoupledDOF(md, &ndof);
  MoorDyn_GetNumberPoints(md, &npoints);
  MoorDyn_GetNumberLines(md, &nlines);
  /* The coupled points in MoorDyn's order (that of their IDs) and the line at each. */
  MoorDynPoint fair[MAX_POINTS];
  MoorDynLine line[MAX_POINTS];
  unsigned int nfair = 0;
  for (unsigned int i = 1; i <= npoints && nfair < MAX_POINTS; ++i) {
    MoorDynPoint p = MoorDyn_GetPoint(md, i);
    int type = 0;
    MoorDyn_GetPointType(p, &type);
    if (type != -1) continue; /* Point::COUPLED */
    unsigned int n = 0;
    MoorDyn_GetPointNAttached(p, &n);
    int end = 0;
    if (n != 1 || MoorDyn_GetPointAttached(p, 0, &line[nfair], &end) != MOORDYN_SUCCESS) {
      fprintf(stderr, "coupled point %u: one line expected\n", i);
      return 1;
    }
    fair[nfair++] = p;
  }
  if (3 * nfair != ndof) {
    fprintf(stderr, "%u coupled points but %u coupled dofs\n", nfair, ndof);
    return 1;
  }
  double x0[3 * MAX_POINTS], x[3 * MAX_POINTS], xd[3 * MAX_POINTS], f[3 * MAX_POINTS];
  for (unsigned int k = 0; k < nfair; ++k) MoorDyn_GetPointPos(fair[k], x0 + 3 * k);
  double s, v, a;
  surge(0.0, &s, &v, &a);
  for (unsigned int i = 0; i < ndof; ++i) {
    x[i] = x0[i] + (i % 3 == 0 ? s : 0.0);
    xd[i] = i % 3 == 0 ? v : 0.0;
  }
  const double cpu0 = cpu();
  if (MoorDyn_Init(md, x, xd) != MOORDYN_SUCCESS) return 1;
  const double cpu_init = cpu() - cpu0;

  double tmin[MAX_POINTS], tmax[MAX_POINTS], fmin[MAX_POINTS], fmax[MAX_POINTS];
  for (unsigned int k = 0; k < nfair; ++k) tmin[k] = fmin[k] = INFINITY, tmax[k] = fmax[k] = 0;
  if (series) {
    fprintf(series, "t");
    for (unsigned int k = 0; k < nfair; ++k)
      fprintf(series, ",end_tension_%u,fairten_%u", k + 1, k + 1);
    fprintf(series, "\n");
  }
  const long steps = lround(duration / h), every = lround(sample / h);
  const double cpu1 = cpu();
  for (long n = 0; n < steps; ++n) {
    double t = n * h, dt = h, s1, v1, a1;
    surge(t, &s, &v, &a);
    surge(t + h, &s1, &v1, &a1);
    for (unsigned int i = 0; i < ndof; ++i) {
      x[i] = x0[i] + (i % 3 == 0 ? s : 0.0);
      xd[i] = i % 3 == 0 ? (s1 - s) / h : 0.0;
    }
    if (MoorDyn_Step(md, x, xd, f, &t, &dt) != MOORDYN_SUCCESS) {
      fprintf(stderr, "MoorDyn_Step failed at t = %g s\n", n * h);
      return 1;
    }
    if ((n + 1) % every) continue;
    const double time = (n + 1) * h;
    if (series) fprintf(series, "%.4f", time);
    for (unsigned int k = 0; k < nfair; ++k) {
      double m[3][3], ten;
      MoorDyn_GetPointM(fair[k], m);
      MoorDyn_GetLineFairTen(line[k], &ten);
      double r2 = 0.0;
      for (int j = 0; j < 3; ++j) {
        const double rj = f[3 * k + j] - m[j][0] * a1;
        r2 += rj * rj;
      }
      const double end = sqrt(r2);
      if (series) fprintf(series, ",%.1f,%.1f", end, ten);
      if (time < from - 1e-9) continue;
      fmin[k] = fmin[k] < end ? fmin[k] : end, fmax[k] = fmax[k] > end ? fmax[k] : end;
      tmin[k] = tmin[k] < ten ? tmin[k] : ten, tmax[k] = tmax[k] > ten ? tmax[k] : ten;
    }
    if (series) fprintf(series, "\n");
  }
  const double cpu_steps = cpu() - cpu1;
  double dtm = 0.0;
  MoorDyn_GetDt(md, &dtm);
  printf("dtM %g s, coupling step %g s, CPU init %.2f s, steps %.2f s\n", dtm, h, cpu_init,
         cpu_steps);
  for (unsigned int k = 0; k < nfair; ++k)
    printf("line %u: end_tension min %.0f max %.0f N; FairTen min %.0f max %.0f N\n", k + 1,
           fmin[k], fmax[k], tmin[k], tmax[k]);
  if (series) fclose(series);
  MoorDyn_Close(md);
  return 0;
}
