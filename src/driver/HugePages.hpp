#pragma once
// Transparent huge pages for the heap. A run first touches its matrices and vectors page by
// page; with 2 MiB pages instead of 4 KiB ones it takes 512 times fewer page faults, which
// a virtual machine pays dearly for; the peak memory stays the same (doc/performance-model.md,
// "Page faults and huge pages", measures it). glibc's malloc asks the kernel for them only
// when its tunable glibc.malloc.hugetlb is set at process start, so the program restarts
// itself once with it. A GLIBC_TUNABLES already set is the user's choice (an empty one
// turns this off) and is left alone, as is a process that valgrind runs.
namespace signorini::detail {

// Replaces the process by itself (the same arguments and PID, so MPI launchers follow) with
// GLIBC_TUNABLES=glibc.malloc.hugetlb=1; returns when it does not apply or cannot be done.
// Call first in main(), before MPI or Kokkos start.
void restartWithHugePages(char** argv);

// Whether this process's malloc asks for transparent huge pages.
bool mallocAsksForHugePages();

}  // namespace signorini::detail
