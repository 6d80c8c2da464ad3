/* STREAM-like triad c = a + s b over three 400 MB arrays: the memory
 * bandwidth one core gets, to compare with the parallel speed-up of the
 * sparse (bandwidth-bound) kernels of contact_fem. Run by run.sh alone and
 * two at a time, one per core. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

int
main(void)
{
  const size_t n = 50 * 1000 * 1000;
  double      *a = malloc(n * sizeof(double)), *b = malloc(n * sizeof(double)),
         *c = malloc(n * sizeof(double));
  if (!a || !b || !c)
    return 1;
  for (size_t i = 0; i < n; ++i)
    {
      a[i] = 1.;
      b[i] = 2.;
      c[i] = 0.;
    }
  struct timespec start, end;
  clock_gettime(CLOCK_MONOTONIC, &start);
  for (int repeat = 0; repeat < 10; ++repeat)
    for (size_t i = 0; i < n; ++i)
      c[i] = a[i] + 1.5 * b[i];
  clock_gettime(CLOCK_MONOTONIC, &end);
  const double seconds = (end.tv_sec - start.tv_sec) + 1e-9 * (end.tv_nsec - start.tv_nsec);
  /* c[7] printed so that the loop is not optimised away. */
  printf("triad %.1f GB/s (check %g)\n", 10. * 3. * n * sizeof(double) / seconds / 1e9, c[7]);
  free(a);
  free(b);
  free(c);
  return 0;
}
