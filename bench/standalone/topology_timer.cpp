// Standalone measurement, not part of the build: the TetMesh constructor (topology build) on
// a saved mesh, A/B between two builds of the library, and a hash of every topology array
// (edges, tetEdges, faces, faceTets, tetFaces, boundary faces and vertices, vertex normals,
// volumes, incidence, total volume, mean edge length) to check that two builds number
// everything identically. Prints process CPU (all threads) and wall time, min / median / max.
// Build and run by hand (bench/RESULTS.md, "branch perf3"):
//   L="/usr/lib/x86_64-linux-gnu/libmuparser.so.2.3.3 -ltbb -lz"
//   g++ -std=c++20 -O2 -DWITH_IO -I. -isystem /usr/include/eigen3
//   bench/standalone/topology_timer.cpp \
//       -o /tmp/topo_dump build/io/libtfd_io.a build/core/libtfd_core.a
//       /usr/lib/x86_64-linux-gnu/libtet.so $L
//   g++ -std=c++20 -O2 -I. -isystem /usr/include/eigen3 bench/standalone/topology_timer.cpp \
//       -o /tmp/topo build/core/libtfd_core.a $L
//   mkdir -p /tmp/perf3; /tmp/topo_dump dump  # TetGen's 1M-tet sphere -> /tmp/perf3/sphere1m.bin
//   /tmp/topo 2 1 hash                        # threads, repetitions, print the hash
//   GLIBC_TUNABLES=glibc.malloc.hugetlb=1 /tmp/topo 2 5
#include <sys/resource.h>
#include <tbb/global_control.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>
static double cpuNow() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
#include "core/tet_mesh.h"
#ifdef WITH_IO
#include "core/surface/primitives.h"
#include "io/tetgen/tetgen_mesher.h"
#endif
using namespace tfd::core;
static std::uint64_t h = 1469598103934665603ULL;
template <class T>
void mix(const std::vector<T>& v) {
  const unsigned char* p = reinterpret_cast<const unsigned char*>(v.data());
  for (std::size_t i = 0; i < v.size() * sizeof(T); ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
}
int main(int argc, char** argv) {
  const char* file = "/tmp/perf3/sphere1m.bin";  // made by "dump"
#ifdef WITH_IO
  if (argc > 1 && !strcmp(argv[1], "dump")) {
    tfd::io::TetgenOptions options;
    options.targetTets = 1e6;
    auto m = tfd::io::tetrahedralize(makePrimitiveForTets(PrimitiveSpec{}, 1e6), options);
    std::ofstream out(file, std::ios::binary);
    std::uint64_t nv = m->vertexCount(), nt = m->tetCount();
    out.write((char*)&nv, 8);
    out.write((char*)&nt, 8);
    out.write((char*)m->positions().data(), nv * sizeof(Vec3));
    out.write((char*)m->tets().data(), nt * sizeof(TetMesh::Tet));
    std::printf("dumped %zu %zu\n", (size_t)nv, (size_t)nt);
    return 0;
  }
#endif
  int threads = argc > 1 ? atoi(argv[1]) : 2, reps = argc > 2 ? atoi(argv[2]) : 5;
  bool hash = argc > 3;
  std::ifstream in(file, std::ios::binary);
  std::uint64_t nv, nt;
  in.read((char*)&nv, 8);
  in.read((char*)&nt, 8);
  std::vector<Vec3> pos(nv);
  std::vector<TetMesh::Tet> tets(nt);
  in.read((char*)pos.data(), nv * sizeof(Vec3));
  in.read((char*)tets.data(), nt * sizeof(TetMesh::Tet));
  tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
  std::vector<double> times, cpus;
  for (int r = 0; r < reps; ++r) {
    auto p = pos;
    auto t = tets;
    auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpuNow();
    {
      TetMesh m(std::move(p), std::move(t));
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      cpus.push_back(cpuNow() - c0);
      if (hash && r == 0) {
        mix(m.edges());
        mix(m.tetEdges());
        mix(m.faces());
        mix(m.faceTets());
        mix(m.tetFaces());
        mix(m.boundaryFaces());
        mix(m.boundaryVertices());
        mix(m.vertexNormals());
        mix(m.tetVolumes());
        std::vector<int> inc;
        for (size_t v = 0; v < m.vertexCount(); ++v)
          for (int x : m.vertexTets(v)) inc.push_back(x);
        mix(inc);
        std::vector<double> s{m.totalVolume(), m.meanEdgeLength()};
        mix(s);
        std::printf("hash %016llx edges %zu faces %zu\n", (unsigned long long)h, m.edges().size(),
                    m.faces().size());
      }
    }
  }
  std::sort(times.begin(), times.end());
  std::sort(cpus.begin(), cpus.end());
  std::printf("cpu min %.0f ms median %.0f ms; ", cpus[0] * 1e3, cpus[cpus.size() / 2] * 1e3);
  std::printf("threads %d: min %.0f ms median %.0f ms max %.0f ms (n=%d)\n", threads,
              times[0] * 1e3, times[times.size() / 2] * 1e3, times.back() * 1e3, reps);
}
