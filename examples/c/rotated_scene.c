/*
 * roughwall from C: the glass-steel scene of Radenkovic & Simonin (2021), Sec. 4
 * (delta_xi = 3.8 deg, delta_zeta = 7.5 deg, Sommerfeld-Huber with the glass-steel preset,
 * 500 um beads, horizontal speed ~ N(5.91, 1.16) m/s, alpha- = -15 deg, beta- = 60 deg),
 * hit by particles in a ROTATED frame: the wall normal is not +y (and given pointing out of
 * the flow, not unit length), the lay direction has a component along the normal, and the
 * wall moves. Each rebound is turned back into the wall's frame, where its angles must follow
 * `rebound stochastic` on the same scene.
 *
 *   rotated_scene stats N OUT.bin   N hits; writes (alpha_out_deg, dbeta_deg) per hit as
 *                                   little-endian doubles; prints means and ns per call
 *   rotated_scene keys              fixed hits in the paper's frame: "pid cidx status" and
 *                                   the rebound velocity's bit patterns, for the identity
 *                                   check against the Rust call
 *
 * Build: cc -O2 -I include examples/c/rotated_scene.c -L target/release -lroughwall \
 *           -Wl,-rpath,$PWD/target/release -lm -o rotated_scene
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "roughwall.h"

static const double PI = 3.14159265358979323846;

/* The wall and the scene's incident direction. */
static rw_wall *make_wall(void) {
  rw_wall_params p;
  char msg[256];
  rw_wall *w = NULL;
  rw_wall_params_default(&p);
  p.delta_xi_deg = 3.8;
  p.delta_zeta_deg = 7.5;
  p.law = RW_LAW_SOMMERFELD_HUBER;
  p.preset = RW_PRESET_GLASS_STEEL;
  p.seed = 2021;
  int s = rw_wall_new(&p, &w, msg, sizeof msg);
  if (s != RW_OK) {
    fprintf(stderr, "rw_wall_new: %s (%s)\n", rw_status_string(s), msg);
    exit(1);
  }
  return w;
}

/* A fixed rotation (rows of R): axis (1, 2, 3)/|.|, angle 1.1 rad. */
static void rotation(double r[3][3]) {
  double a[3] = {1.0, 2.0, 3.0}, n = sqrt(14.0), t = 1.1;
  for (int i = 0; i < 3; i++) a[i] /= n;
  double c = cos(t), s = sin(t), C = 1.0 - c;
  r[0][0] = c + a[0] * a[0] * C;        r[0][1] = a[0] * a[1] * C - a[2] * s; r[0][2] = a[0] * a[2] * C + a[1] * s;
  r[1][0] = a[1] * a[0] * C + a[2] * s; r[1][1] = c + a[1] * a[1] * C;        r[1][2] = a[1] * a[2] * C - a[0] * s;
  r[2][0] = a[2] * a[0] * C - a[1] * s; r[2][1] = a[2] * a[1] * C + a[0] * s; r[2][2] = c + a[2] * a[2] * C;
}

static void rot(double r[3][3], const double v[3], double out[3]) {
  for (int i = 0; i < 3; i++) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
}

static void rot_t(double r[3][3], const double v[3], double out[3]) {
  for (int i = 0; i < 3; i++) out[i] = r[0][i] * v[0] + r[1][i] * v[1] + r[2][i] * v[2];
}

/* splitmix64 and a normal by Box-Muller: the C side's own incident speeds. */
static uint64_t sm_state = 12345;
static uint64_t splitmix64(void) {
  uint64_t z = (sm_state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}
static double uniform(void) { return ((splitmix64() >> 11) + 0.5) * (1.0 / 9007199254740992.0); }
static double normal(void) { return sqrt(-2.0 * log(uniform())) * cos(2.0 * PI * uniform()); }

static double wrap(double x) { /* into (-180, 180] */
  x = fmod(x, 360.0);
  if (x <= -180.0) x += 360.0;
  if (x > 180.0) x -= 360.0;
  return x;
}

static int stats(long n, const char *path) {
  rw_wall *w = make_wall();
  double r[3][3];
  rotation(r);
  const double alpha = -15.0 * PI / 180.0, beta = 60.0 * PI / 180.0;
  const double ey[3] = {0.0, -2.5, 0.0};              /* normal out of the flow, length 2.5 */
  const double lay_local[3] = {1.0, 0.4, 0.0};        /* not in the wall plane */
  const double vwall_local[3] = {0.3, 0.0, -0.2};     /* the wall slides in its plane */
  rw_hit h;
  memset(&h, 0, sizeof h);
  rot(r, ey, h.normal);
  rot(r, lay_local, h.lay);
  rot(r, vwall_local, h.wall_velocity);
  h.diameter = 500e-6;
  FILE *f = fopen(path, "wb");
  if (!f) { perror(path); return 1; }
  double sum_a = 0.0, sum_d = 0.0;
  struct timespec t0, t1;
  double seconds = 0.0;
  for (long i = 0; i < n; i++) {
    double uh;
    do uh = 5.91 + 1.16 * normal(); while (uh <= 0.0);
    double speed = uh / cos(alpha);
    double u_local[3] = {speed * cos(alpha) * cos(beta), speed * sin(alpha), -speed * cos(alpha) * sin(beta)};
    double u_rel[3];
    rot(r, u_local, u_rel);
    for (int k = 0; k < 3; k++) h.velocity[k] = u_rel[k] + h.wall_velocity[k];
    h.particle_id = (uint64_t)i;
    h.collision_index = 0;
    rw_result out;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int s = rw_rebound(w, &h, &out);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    seconds += (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
    if (s != RW_OK) { fprintf(stderr, "hit %ld: %s\n", i, rw_status_string(s)); return 1; }
    double g[3], l[3];
    for (int k = 0; k < 3; k++) g[k] = out.velocity[k] - h.wall_velocity[k];
    rot_t(r, g, l);
    double norm = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    double rec[2];
    rec[0] = asin(l[1] / norm) * 180.0 / PI;                          /* alpha+ */
    rec[1] = wrap(atan2(-l[2], l[0]) * 180.0 / PI - 60.0);            /* beta+ - beta- */
    sum_a += rec[0];
    sum_d += rec[1];
    fwrite(rec, sizeof rec, 1, f);
  }
  fclose(f);
  printf("hits %ld mean_alpha_out_deg %.6f mean_dbeta_deg %.6f ns_per_call %.1f version %s\n",
         n, sum_a / n, sum_d / n, 1e9 * seconds / n, rw_version());
  rw_wall_free(w);
  return 0;
}

static int keys(void) {
  rw_wall *w = make_wall();
  for (uint64_t pid = 0; pid < 20; pid++) {
    rw_hit h;
    memset(&h, 0, sizeof h);
    double uh = 4.0 + 0.25 * (double)pid;
    h.velocity[0] = uh * 0.5;
    h.velocity[1] = -0.35 * uh;
    h.velocity[2] = -uh * 0.866;
    h.spin[2] = 100.0 * (double)pid;
    h.normal[1] = 1.0;
    h.lay[0] = 1.0;
    h.diameter = 500e-6;
    h.particle_id = pid;
    h.collision_index = pid % 3;
    rw_result out;
    int s = rw_rebound(w, &h, &out);
    uint64_t b[6];
    memcpy(b, out.velocity, 24);
    memcpy(b + 3, out.spin, 24);
    printf("%llu %llu %d %016llx %016llx %016llx %016llx %016llx %016llx %u\n",
           (unsigned long long)pid, (unsigned long long)h.collision_index, s,
           (unsigned long long)b[0], (unsigned long long)b[1], (unsigned long long)b[2],
           (unsigned long long)b[3], (unsigned long long)b[4], (unsigned long long)b[5],
           out.candidate_walls);
  }
  /* Bad input is a status, not a crash or NaN. */
  rw_hit bad;
  memset(&bad, 0, sizeof bad);
  bad.velocity[1] = -1.0;
  rw_result out;
  int s1 = rw_rebound(w, &bad, &out);                     /* zero normal */
  bad.normal[1] = 1.0;
  bad.lay[1] = 1.0;
  int s2 = rw_rebound(w, &bad, &out);                     /* lay parallel to the normal */
  bad.lay[0] = 1.0;
  bad.diameter = -1.0;
  int s3 = rw_rebound(w, &bad, &out);                     /* negative diameter */
  bad.diameter = 1e-3;
  bad.velocity[0] = NAN;
  int s4 = rw_rebound(w, &bad, &out);                     /* NaN */
  int s5 = rw_rebound(w, NULL, &out);                     /* NULL */
  printf("bad %d %d %d %d %d %d\n", s1, s2, s3, s4, s5, isnan(out.velocity[0]) ? 1 : 0);
  rw_wall_free(w);
  return 0;
}

int main(int argc, char **argv) {
  if (argc >= 4 && strcmp(argv[1], "stats") == 0) return stats(atol(argv[2]), argv[3]);
  if (argc >= 2 && strcmp(argv[1], "keys") == 0) return keys();
  fprintf(stderr, "usage: %s stats N OUT.bin | %s keys\n", argv[0], argv[0]);
  return 2;
}
