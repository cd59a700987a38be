// Large arrays of the curvature computation, mapped in before they are written. On the
// development machine (a virtual machine) a page's first write costs about 3 ms per MB
// through page faults and 0.7 ms per MB when the kernel maps the pages in one call
// (MADV_POPULATE_WRITE, Linux 5.14), and the 1-ring of a million vertices writes a few
// hundred MB. Elsewhere the hint is ignored and the pages fault in as usual.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <vector>

namespace plumbago::curvature {

// Asks the kernel to map in the whole pages of [data, data + bytes) for writing.
inline void populate_pages(void* data, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE)), begin = (uintptr_t(data) + page - 1) & ~(page - 1),
                  end = (uintptr_t(data) + bytes) & ~(page - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)data, (void)bytes;
#endif
}

// v.assign(n, value), with v's new memory mapped in first.
template <class T>
void assign_populated(std::vector<T>& v, size_t n, const T& value = T()) {
  std::vector<T> fresh;
  fresh.reserve(n);
  populate_pages(fresh.data(), n * sizeof(T));
  fresh.assign(n, value);
  v.swap(fresh);
}

}  // namespace plumbago::curvature
