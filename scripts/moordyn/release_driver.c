/* Release the free point of a MoorDyn-C input of scripts/moordyn/write_ex8_input.py (flexmoor's
 * Example 8, cases/seed/ex8-relaxation-test.yaml): the buoy, a Free point, starts where the input
 * puts it, at rest, on the line MoorDyn lays between the anchor and it (its elastic catenary,
 * MoorDyn_Init_NoIC: no initial-condition solve, which would let the buoy rise to its
 * equilibrium first), and is left to rise for DURATION seconds at time step DT.
 *
 * Printed: the buoy's position at 1 s and 3 s and its largest speed (records every SAMPLE
 * seconds, flexmoor's output interval), the largest anchor force (the anchor node's net force, the
 * first segment's tension plus the half segment's weight and drag: the lumped-mass form of
 * flexmoor's end_tension), and the anchor force after the first step (the held rope's). SI.
 *
 * Usage: release_driver LINES.txt DURATION DT [SAMPLE]   (SAMPLE default 0.005 s)
 * Build (against an installed MoorDyn-C, include dir .../include/moordyn):
 *   cc -O2 -o release_driver release_driver.c -I$MD/include/moordyn -L$MD/lib -lmoordyn -lm
 */
#include <MoorDyn2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static double norm(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

int main(int argc, char** argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: %s LINES.txt DURATION DT [SAMPLE]\n", argv[0]);
    return 2;
  }
  const double duration = atof(argv[2]), h = atof(argv[3]);
  const double sample = argc > 4 ? atof(argv[4]) : 0.005;
  MoorDyn md = MoorDyn_Create(argv[1]);
  if (!md) return 1;
  MoorDyn_SetVerbosity(md, MOORDYN_WRN_LEVEL);
  unsigned int npoints = 0;
  MoorDyn_GetNumberPoints(md, &npoints);
  MoorDynPoint buoy = NULL;
  for (unsigned int i = 1; i <= npoints; ++i) {
    MoorDynPoint p = MoorDyn_GetPoint(md, i);
    int type = 0;
    MoorDyn_GetPointType(p, &type);
    if (type == 0) buoy = p; /* Point::FREE */
  }
  MoorDynLine line = MoorDyn_GetLine(md, 1);
  if (!buoy || !line || MoorDyn_Init_NoIC(md, NULL, NULL) != MOORDYN_SUCCESS) return 1;
  double r0[3], r[3], v[3], fa[3];
  MoorDyn_GetPointPos(buoy, r0);
  MoorDyn_GetLineNodePos(line, 0, r); /* the anchor */
  const double anchor[3] = {r[0], r[1], r[2]};
  double t = 0.0, dt = 0.0, speed_max = 0.0, tension_max = 0.0;
  printf("held: buoy at x %.6f z %.6f m from the anchor\n", r0[0] - anchor[0], r0[2] - anchor[2]);
  const long steps = lround(duration / h), every = lround(sample / h);
  for (long n = 0; n < steps; ++n) {
    t = n * h, dt = h;
    if (MoorDyn_Step(md, NULL, NULL, NULL, &t, &dt) != MOORDYN_SUCCESS) {
      fprintf(stderr, "MoorDyn_Step failed at t = %g s\n", n * h);
      return 1;
    }
    if (n == 0) {
      MoorDyn_GetLineNodeForce(line, 0, fa);
      printf("first step: anchor force %.6g N\n", norm(fa));
    }
    if ((n + 1) % every) continue;
    const double time = (n + 1) * h;
    MoorDyn_GetPointPos(buoy, r);
    MoorDyn_GetPointVel(buoy, v);
    MoorDyn_GetLineNodeForce(line, 0, fa);
    speed_max = fmax(speed_max, norm(v));
    tension_max = fmax(tension_max, norm(fa));
    const long ms = lround(time * 1000.0);
    if (ms % 1000 == 0)
      printf("t %.0f s: buoy at x %.6f z %.6f m from the anchor\n", time, r[0] - anchor[0],
             r[2] - anchor[2]);
  }
  printf("max speed %.6f m/s, max anchor force %.6g N\n", speed_max, tension_max);
  MoorDyn_Close(md);
  return 0;
}
