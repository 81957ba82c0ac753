#include "driver/HugePages.hpp"

#include <cstdlib>
#include <cstring>

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#define SIGNORINI_CAN_RESTART 1
#endif
#if __has_include(<valgrind/valgrind.h>)
#include <valgrind/valgrind.h>
#endif

namespace signorini::detail {
namespace {
constexpr const char* kTunable = "glibc.malloc.hugetlb=1";
}

void restartWithHugePages(char** argv) {
#ifdef SIGNORINI_CAN_RESTART
  if (std::getenv("GLIBC_TUNABLES")) return;
#ifdef RUNNING_ON_VALGRIND
  if (RUNNING_ON_VALGRIND) return;  // memcheck must see this process, not a native restart
#endif
  if (setenv("GLIBC_TUNABLES", kTunable, 0) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("GLIBC_TUNABLES");  // the restart failed: go on as started
#else
  (void)argv;
#endif
}

bool mallocAsksForHugePages() {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return tunables && std::strstr(tunables, kTunable);
}

}  // namespace signorini::detail
