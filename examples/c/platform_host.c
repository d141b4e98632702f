/* A host program that drives a case's platform through flexmoor's C API, step by step, with a
 * prescribed 6-dof motion: each dof a sine brought in over a ramp (the smoothstep
 * 10 x^3 - 15 x^4 + 6 x^5, whose rate and acceleration vanish at both ends, as flexmoor's
 * `ramp:`). It prints the platform's loads every 10 s of simulated time and writes the results
 * files.
 *
 *   platform_host [CASE] [-o DIR] [--dt DT] [--duration T] [--ramp T]
 *                 [--DOF AMPLITUDE:PERIOD[:PHASE]] ...
 *
 * CASE defaults to oc4-semi-surge; DOF is surge, sway, heave (length) or roll, pitch, yaw (deg).
 * With no DOF given, the motion is surge 2 m at 10 s, ramped in over 10 s: oc4-semi-surge's own,
 * so that the run equals `flexmoor run oc4-semi-surge` (dt 0.1 s, 600 s). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "flexmoor.h"

static const char* const kDofs[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

struct motion {
  double amplitude[6], omega[6], phase[6], ramp;
};

/* s f(t) with its first and second derivatives; f = A sin(w t + phase). */
static void dof_state(const struct motion* m, int k, double t, double* x, double* v, double* a) {
  const double arg = m->omega[k] * t + m->phase[k];
  const double f = m->amplitude[k] * sin(arg);
  const double df = m->amplitude[k] * m->omega[k] * cos(arg);
  const double ddf = -m->amplitude[k] * m->omega[k] * m->omega[k] * sin(arg);
  double s = 1.0, ds = 0.0, dds = 0.0;
  if (m->ramp > 0.0) {
    const double r = t / m->ramp;
    if (r <= 0.0) {
      s = 0.0;
    } else if (r < 1.0) {
      const double r2 = r * r;
      s = r2 * r * (10.0 - 15.0 * r + 6.0 * r2);
      ds = 30.0 * r2 * (1.0 - r) * (1.0 - r) / m->ramp;
      dds = 60.0 * r * (1.0 - r) * (1.0 - 2.0 * r) / (m->ramp * m->ramp);
    }
  }
  *x = s * f;
  *v = ds * f + s * df;
  *a = dds * f + 2.0 * ds * df + s * ddf;
}

static void state_at(const struct motion* m, double t, double* x, double* v, double* a) {
  for (int k = 0; k < 6; ++k) dof_state(m, k, t, &x[k], &v[k], &a[k]);
}

static int check(flexmoor_t h, int code, const char* what) {
  if (code != FLEXMOOR_OK) fprintf(stderr, "platform_host: %s: %s\n", what, flexmoor_last_error(h));
  return code;
}

static void print_line(void* user_data, int level, const char* line) {
  (void)user_data;
  if (level > 0) fprintf(stderr, "%s\n", line);
}

int main(int argc, char** argv) {
  const char* case_name = "oc4-semi-surge";
  const char* output = "results/platform_host";
  double dt = 0.1, duration = 600.0;
  const double pi = acos(-1.0);
  struct motion m = {{0}, {0}, {0}, 10.0};
  int given = 0;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "-o") && i + 1 < argc) {
      output = argv[++i];
    } else if (!strcmp(argv[i], "--dt") && i + 1 < argc) {
      dt = atof(argv[++i]);
    } else if (!strcmp(argv[i], "--duration") && i + 1 < argc) {
      duration = atof(argv[++i]);
    } else if (!strcmp(argv[i], "--ramp") && i + 1 < argc) {
      m.ramp = atof(argv[++i]);
    } else if (!strncmp(argv[i], "--", 2) && i + 1 < argc) {
      int k = 0;
      while (k < 6 && strcmp(argv[i] + 2, kDofs[k])) ++k;
      double amplitude = 0.0, period = 0.0, phase = 0.0;
      if (k == 6 || sscanf(argv[i + 1], "%lf:%lf:%lf", &amplitude, &period, &phase) < 2 ||
          !(period > 0.0)) {
        fprintf(stderr, "platform_host: %s %s: expected --DOF AMPLITUDE:PERIOD[:PHASE]\n",
                argv[i], argv[i + 1]);
        return 1;
      }
      ++i;
      const double unit = k < 3 ? 1.0 : pi / 180.0;
      m.amplitude[k] = amplitude * unit;
      m.omega[k] = 2.0 * acos(-1.0) / period;
      m.phase[k] = phase;
      given = 1;
    } else if (argv[i][0] != '-') {
      case_name = argv[i];
    } else {
      fprintf(stderr, "platform_host: unknown option %s\n", argv[i]);
      return 1;
    }
  }
  if (!given) { /* oc4-semi-surge's motion */
    m.amplitude[0] = 2.0;
    m.omega[0] = 2.0 * acos(-1.0) / 10.0;
  }

  flexmoor_t h = NULL;
  int code = check(h, flexmoor_create(case_name, &h), "reading the case");
  if (!code) code = check(h, flexmoor_set_logger(h, print_line, NULL), "logger");
  if (!code) code = check(h, flexmoor_couple(h, "platform"), "coupling the platform");
  if (!code) code = check(h, flexmoor_set_output(h, output), "output");
  double x[6], v[6], a[6], f[6], t = 0.0;
  state_at(&m, 0.0, x, v, a);
  if (!code) code = check(h, flexmoor_init(h, 6, x, v), "statics");
  if (!code) code = check(h, flexmoor_time(h, &t), "time");
  const double start = t;
  const long steps = lround(duration / dt);
  for (long n = 0; !code && n < steps; ++n) {
    state_at(&m, start + (n + 1) * dt, x, v, a);
    code = check(h, flexmoor_step(h, 6, x, v, a, f, &t, dt), "step");
    if (!code && (n + 1) % lround(10.0 / dt) == 0)
      printf("t = %6.1f s  surge %7.3f  Fx %12.1f  Fz %12.1f  My %14.1f\n", t, x[0], f[0], f[2],
             f[4]);
  }
  if (!code) code = check(h, flexmoor_finish(h), "finishing");
  int count = 0;
  if (!code && !flexmoor_summary_count(h, &count))
    for (int k = 0; k < count; ++k) {
      const char* name;
      double value;
      flexmoor_summary_value(h, k, &name, &value);
      printf("%-24s %.8g\n", name, value);
    }
  flexmoor_close(h);
  return code;
}
