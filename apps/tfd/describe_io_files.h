#pragma once
// Describers for `tfd info` of the io layer's file kinds (see file_describers.h). Each throws
// std::exception (core::Error) naming the file when it cannot be read.
#include <filesystem>
#include <iosfwd>

namespace tfd::cli {

int describeMesh(const std::filesystem::path& file, std::ostream& out);
int describeVdb(const std::filesystem::path& file, std::ostream& out);
int describeExr(const std::filesystem::path& file, std::ostream& out);
int describeCurvesJson(const std::filesystem::path& file, std::ostream& out);

}  // namespace tfd::cli
