/*
 * A single rw_rebound call starts no thread (issue 9, item 8; built and run by
 * tests/c_library.rs in a fresh process). Counts the entries of /proc/self/task:
 *   start   at the top of main (the library is loaded by then);
 *   walls   after building the walls;
 *   calls   the most seen during 10^4 rw_rebound calls on each wall (counted every 100
 *           calls and after the last one);
 *   own     with one thread of this program's own running: the count must see it;
 *   batch   after rw_rebound_batch with 4 threads: they are joined before it returns
 *           (and gone from /proc/self/task within 1 s).
 * Prints "start walls calls own batch" on one line.
 */
#include <dirent.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "roughwall.h"

static int count_threads(void) {
  DIR *d = opendir("/proc/self/task");
  if (d == NULL) {
    perror("/proc/self/task");
    exit(1);
  }
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d)) != NULL)
    if (e->d_name[0] != '.') n++;
  closedir(d);
  return n;
}

static rw_wall *wall(double dxi, double dzeta, int law, int preset, int model, double dgamma) {
  rw_wall_params p;
  char msg[256];
  rw_wall *w = NULL;
  rw_wall_params_default(&p);
  p.delta_xi_deg = dxi;
  p.delta_zeta_deg = dzeta;
  p.law = law;
  p.preset = preset;
  p.model = model;
  p.delta_gamma_deg = dgamma;
  p.seed = 7;
  int s = rw_wall_new(&p, &w, msg, sizeof msg);
  if (s != RW_OK) {
    fprintf(stderr, "rw_wall_new: %s (%s)\n", rw_status_string(s), msg);
    exit(1);
  }
  return w;
}

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t cond = PTHREAD_COND_INITIALIZER;
static int released = 0;

static void *waiter(void *arg) {
  (void)arg;
  pthread_mutex_lock(&lock);
  while (!released) pthread_cond_wait(&cond, &lock);
  pthread_mutex_unlock(&lock);
  return NULL;
}

int main(void) {
  int start = count_threads();
  rw_wall *walls[3] = {
      /* the Sec. 4 glass-steel wall, the paper's model */
      wall(3.8, 7.5, RW_LAW_SOMMERFELD_HUBER, RW_PRESET_GLASS_STEEL,
           RW_MODEL_RADENKOVIC_SIMONIN_2021, NAN),
      /* Sommerfeld & Huber 1999 (shadow effect, repeated hits) */
      wall(3.8, 7.5, RW_LAW_SOMMERFELD_HUBER, RW_PRESET_GLASS_STEEL,
           RW_MODEL_SOMMERFELD_HUBER_1999, 5.0),
      /* a smooth elastic wall */
      wall(0.0, 0.0, RW_LAW_ELASTIC, RW_PRESET_NONE, RW_MODEL_RADENKOVIC_SIMONIN_2021,
           NAN),
  };
  int after_walls = count_threads();
  int most = after_walls;
  for (int k = 0; k < 3; k++) {
    for (int i = 0; i < 10000; i++) {
      rw_hit h = {
          .velocity = {5.0 + 1e-4 * i, -1.0 - 1e-4 * i, 0.5},
          .spin = {0.0, 0.0, 10.0},
          .normal = {0.0, -1.0, 0.0},
          .lay = {1.0, 0.0, 0.0},
          .wall_velocity = {0.0, 0.0, 0.0},
          .diameter = 500e-6,
          .particle_id = (uint64_t)i,
          .collision_index = 0,
      };
      rw_result r;
      int s = rw_rebound(walls[k], &h, &r);
      if (s != RW_OK) {
        fprintf(stderr, "rw_rebound: %s\n", rw_status_string(s));
        return 1;
      }
      if (i % 100 == 99) {
        int n = count_threads();
        if (n > most) most = n;
      }
    }
  }

  pthread_t t;
  if (pthread_create(&t, NULL, waiter, NULL) != 0) return 1;
  int own = count_threads();
  pthread_mutex_lock(&lock);
  released = 1;
  pthread_cond_broadcast(&cond);
  pthread_mutex_unlock(&lock);
  pthread_join(t, NULL);

  enum { N = 1000 };
  static double ux[N], uy[N], uz[N], nx[N], ny[N], nz[N], lx[N], ly[N], lz[N], d[N];
  static uint64_t pid[N], cid[N];
  static int status[N];
  for (int i = 0; i < N; i++) {
    ux[i] = 5.0;
    uy[i] = -1.0;
    uz[i] = 0.1 * i;
    nx[i] = 0.0;
    ny[i] = 1.0;
    nz[i] = 0.0;
    lx[i] = 1.0;
    ly[i] = 0.0;
    lz[i] = 0.0;
    d[i] = 500e-6;
    pid[i] = (uint64_t)i;
    cid[i] = 0;
  }
  rw_batch b = {
      .n = N,
      .ux = ux, .uy = uy, .uz = uz,
      .nx = nx, .ny = ny, .nz = nz,
      .lx = lx, .ly = ly, .lz = lz,
      .diameter = d,
      .particle_id = pid,
      .collision_index = cid,
      .out_ux = ux, .out_uy = uy, .out_uz = uz,
      .out_status = status,
  };
  if (rw_rebound_batch(walls[0], &b, 4) != RW_OK) return 1;
  for (int i = 0; i < N; i++)
    if (status[i] != RW_OK) return 1;
  /* Joined threads leave /proc/self/task as the kernel reaps them: allow it 1 s. */
  int batch = count_threads();
  for (int tries = 0; batch > start && tries < 100; tries++) {
    struct timespec ms10 = {0, 10000000};
    nanosleep(&ms10, NULL);
    batch = count_threads();
  }

  for (int k = 0; k < 3; k++) rw_wall_free(walls[k]);
  printf("%d %d %d %d %d\n", start, after_walls, most, own, batch);
  return 0;
}
