#pragma once
// Describers for `tfd info` of the io layer's file kinds (see file_describers.h). Each throws
// std::exception (core::Error) naming the file when it cannot be read.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace tfd::cli {

/// Label/value rows in display order, e.g. {"format", "Gmsh .msh 4.1 (ASCII) (tet mesh)"}.
using Rows = std::vector<std::pair<std::string, std::string>>;
/// The rows as aligned "label: value" lines; a row with an empty label continues the one above.
std::string formatRows(const Rows& rows);

/// A mesh file's summary: format, counts, bounds, volume, mean edge length and the topology
/// of its surface ("closed, Euler characteristic 2 (genus 0)"). Reads and validates the file
/// completely; throws like the io readers.
Rows describeMeshFile(const std::filesystem::path& path);

int describeMesh(const std::filesystem::path& file, std::ostream& out);
int describeVdb(const std::filesystem::path& file, std::ostream& out);
int describeExr(const std::filesystem::path& file, std::ostream& out);
int describeCurvesJson(const std::filesystem::path& file, std::ostream& out);
/// A .vtu: describeMeshFile's rows, then its encoding and point and cell arrays.
int describeVtu(const std::filesystem::path& file, std::ostream& out);
/// A .vtp (curves, lines, tubes): counts of points, lines, polygons, and its arrays.
int describeVtp(const std::filesystem::path& file, std::ostream& out);

}  // namespace tfd::cli
