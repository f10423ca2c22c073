#pragma once
// Shared pieces of the libFuzzer targets (see fuzz/README.md): the input as a file, and what
// a target may assert. A reader must throw core::Error (our typed error, naming the file) or
// return something that passes its own validity check; anything else is a finding, reported
// by aborting with a message so libFuzzer saves the input.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <typeinfo>

#include "core/error.h"
#include "core/surface/surface_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::fuzz {

/// Writes `data` to a per-process scratch file whose name ends in `fileName` (e.g. "in.off")
/// and returns its path. The readers take paths, as users give them.
std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size,
                                const std::string& fileName);

/// Prints "tfd fuzz finding: <what>" and aborts (libFuzzer keeps the input as a crash file).
[[noreturn]] void finding(const std::string& what);

/// Readers' contract for surface meshes (io/mesh/surface_readers.h): at least one triangle,
/// every index in range, every coordinate finite. A finding otherwise.
void checkSurface(const core::SurfaceMesh& mesh);
/// A tet mesh a reader returned must pass TetMesh::validate again.
void checkTetMesh(const core::TetMesh& mesh);

/// A message must name `file` and contain no control bytes other than newline and tab.
void checkMessage(const std::filesystem::path& file, std::string_view message);

/// Runs `read()`; core::Error is the expected failure (its message must name the input file
/// and contain no raw control bytes), any other exception is a finding.
template <class Read>
void expectReadOrError(const std::filesystem::path& file, Read&& read) {
  try {
    read();
  } catch (const core::Error& e) {
    checkMessage(file, e.what());
  } catch (const std::exception& e) {
    finding(std::string("not a core::Error: ") + typeid(e).name() + ": " + e.what());
  }
}

/// Sets a small memory budget (256 MB) once, so that what an input announces is checked
/// against it (core/memory_budget.h) well below libFuzzer's RSS limit.
void useSmallMemoryBudget();

}  // namespace tfd::fuzz
