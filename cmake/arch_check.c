/* Exit 0 when this CPU and OS run x86-64-v3 code (AVX, AVX2, FMA, BMI1/2, F16C, MOVBE, LZCNT and
   the OS saving the YMM registers); used at configure time by SeflexCompileOptions.cmake. */
#include <cpuid.h>

int main(void) {
  unsigned a, b, c, d;
  if (!__get_cpuid(1, &a, &b, &c, &d)) return 1;
  const int fma = (c >> 12) & 1, movbe = (c >> 22) & 1, osxsave = (c >> 27) & 1, avx = (c >> 28) & 1,
            f16c = (c >> 29) & 1;
  if (!(fma && movbe && osxsave && avx && f16c)) return 1;
  unsigned xcr0_lo, xcr0_hi;
  __asm__ volatile("xgetbv" : "=a"(xcr0_lo), "=d"(xcr0_hi) : "c"(0));
  if ((xcr0_lo & 6) != 6) return 1; /* XMM and YMM state enabled by the OS */
  if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return 1;
  const int bmi1 = (b >> 3) & 1, avx2 = (b >> 5) & 1, bmi2 = (b >> 8) & 1;
  if (!(bmi1 && avx2 && bmi2)) return 1;
  if (!__get_cpuid(0x80000001, &a, &b, &c, &d)) return 1;
  return ((c >> 5) & 1) ? 0 : 1; /* LZCNT (ABM) */
}
