#include "fuzz/fuzz_support.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>

#include "core/memory_budget.h"
#include "core/surface/surface_cavities.h"
#include "core/surface/surface_check.h"
#include "core/surface/surface_holes.h"
#include "core/surface/surface_orient.h"
#include "core/surface/surface_weld.h"

namespace tfd::fuzz {

namespace {

void removeScratchFolder();

/// A per-process folder, removed at exit (libFuzzer ends with exit()). Never destroyed, so the
/// exit handler may still read it.
const std::filesystem::path& scratchFolder() {
  static const auto* folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    // A fixed-width name: messages quote the path, and coverage counts the characters a
    // message loop visits, so a path whose length followed the pid would steer the mutations
    // differently from run to run and break `scripts/fuzz --runs` determinism.
    char name[32];
    std::snprintf(name, sizeof name, "tfd-fuzz-%010ld", static_cast<long>(::getpid()));
    auto* p = new std::filesystem::path(std::filesystem::path(tmp && *tmp ? tmp : "/tmp") / name);
    std::filesystem::create_directories(*p);
    std::atexit(removeScratchFolder);
    return p;
  }();
  return *folder;
}

void removeScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(scratchFolder(), ignored);
}

}  // namespace

std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size,
                                const std::string& fileName) {
  const std::filesystem::path path = scratchFolder() / fileName;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) finding("cannot write the scratch file " + path.string());
  return path;
}

void finding(const std::string& what) {
  std::fprintf(stderr, "tfd fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

void checkSurface(const core::SurfaceMesh& mesh) {
  if (mesh.triangles.empty()) finding("a surface reader returned a mesh without triangles");
  const long n = static_cast<long>(mesh.positions.size());
  for (const auto& p : mesh.positions)
    if (!p.allFinite()) finding("a surface reader returned a non-finite position");
  for (const auto& t : mesh.triangles)
    for (int v : t)
      if (v < 0 || v >= n) finding("a surface reader returned an out-of-range index");
  // What TetMesh does with it before TetGen (io/tetgen/surface_meshing.cpp).
  core::SurfaceMesh s = mesh;
  core::weldCloseVertices(s, 1e-3 * core::medianEdgeLength(s));
  core::removeRepeatedTriangles(s);
  core::fillHoles(s, 64);
  const std::size_t triangles = s.triangles.size();
  core::orientConsistently(s);
  if (s.triangles.size() != triangles) finding("orienting the triangles changed their number");
  for (const auto& t : s.triangles)
    for (int v : t)
      if (v < 0 || v >= int(s.positions.size())) finding("welding left an out-of-range index");
  if (core::closedSurfaceProblems(s).empty())
    for (const core::Vec3& p : core::cavityPoints(s))
      if (!p.allFinite()) finding("a void's point is not finite");
}

void checkTetMesh(const core::TetMesh& mesh) {
  const auto problems = core::TetMesh::validate(mesh.positions(), mesh.tets());
  if (!problems.empty()) finding("a tet-mesh reader returned an invalid mesh: " + problems[0]);
}

void checkMessage(const std::filesystem::path& file, std::string_view message) {
  if (message.find(file.filename().string()) == std::string_view::npos)
    finding("an error message does not name the file: " + std::string(message));
  for (unsigned char c : message)
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f)
      finding("an error message echoes a raw control byte: " + std::string(message));
}

void useSmallMemoryBudget() {
  static const bool once = [] {
    core::setMemoryBudget(std::uint64_t(256) << 20);
    return true;
  }();
  (void)once;
}

}  // namespace tfd::fuzz

// The fuzz targets' stand-in for the address-space cap `tfd` sets from its memory budget
// (core/memory_budget.h). AddressSanitizer reserves its shadow memory, so no cap can be set
// under it, and its operator new aborts ("out-of-memory") where the released binary throws
// std::bad_alloc, which our readers turn into an error naming the file. So new and delete go
// through malloc and free here: with allocator_may_return_null, an allocation above the
// targets' 256 MB budget returns null and new throws, as under the cap. ASAN_OPTIONS still
// overrides each flag. Without ASan (scripts/fuzz --fast) new refuses the same sizes itself.
extern "C" const char* __asan_default_options() {
  return "allocator_may_return_null=1:max_allocation_size_mb=256";
}

namespace {

constexpr std::size_t kLargestAllocation = std::size_t(256) << 20;

void* allocateOrThrow(std::size_t size, std::size_t alignment = 0) {
  if (size > kLargestAllocation) throw std::bad_alloc();
  if (size == 0) size = 1;
  void* p = alignment > alignof(std::max_align_t)
                ? std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment)
                : std::malloc(size);
  if (!p) throw std::bad_alloc();
  return p;
}

}  // namespace

void* operator new(std::size_t size) { return allocateOrThrow(size); }
void* operator new[](std::size_t size) { return allocateOrThrow(size); }
void* operator new(std::size_t size, std::align_val_t a) {
  return allocateOrThrow(size, std::size_t(a));
}
void* operator new[](std::size_t size, std::align_val_t a) {
  return allocateOrThrow(size, std::size_t(a));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return std::malloc(size ? size : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
