#include "io/vtk/vtu_writer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include "core/error.h"
#include "io/atomic_file.h"

namespace tfd::io {

namespace {

std::string describe(const char* where, const NamedArray& a) {
  return std::string(where) + " array '" + a.name + "'";
}

void validate(const std::vector<NamedArray>& arrays, std::size_t tuples, const char* where,
              const std::string& file) {
  std::set<std::string> names;
  for (const auto& a : arrays) {
    if (a.name.empty()) throw core::Error(file + ": a " + where + " array has no name");
    if (!names.insert(a.name).second) {
      throw core::Error(file + ": " + describe(where, a) + " is given twice");
    }
    if (a.components < 1) {
      throw core::Error(file + ": " + describe(where, a) + " has " + std::to_string(a.components) +
                        " components");
    }
    const std::size_t expected = tuples * std::size_t(a.components);
    if (a.values.size() != expected) {
      throw core::Error(file + ": " + describe(where, a) + " has " +
                        std::to_string(a.values.size()) + " values, expected " +
                        std::to_string(expected) + " (" + std::to_string(tuples) + " x " +
                        std::to_string(a.components) + ")");
    }
    double lo = 0, hi = 0;
    switch (a.type) {
      case VtkType::UInt8:
        lo = 0, hi = 255;
        break;
      case VtkType::Int32:
        lo = std::numeric_limits<std::int32_t>::min(),
        hi = std::numeric_limits<std::int32_t>::max();
        break;
      case VtkType::Int64:
        lo = -9.007199254740992e15, hi = 9.007199254740992e15;
        break;
      default:
        continue;
    }
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      const double v = a.values[i];
      if (!(v >= lo && v <= hi) || v != std::floor(v)) {
        throw core::Error(file + ": " + describe(where, a) + " is " + vtkTypeName(a.type) +
                          " but value " + std::to_string(i) + " is " + std::to_string(v));
      }
    }
  }
}

template <typename T>
std::vector<T> convert(const std::vector<double>& values) {
  return std::vector<T>(values.begin(), values.end());
}

void writeArray(VtkXmlWriter& xml, const NamedArray& a) {
  switch (a.type) {
    case VtkType::UInt8:
      xml.dataArray(a.name, a.components,
                    std::span<const std::uint8_t>(convert<std::uint8_t>(a.values)));
      break;
    case VtkType::Int32:
      xml.dataArray(a.name, a.components,
                    std::span<const std::int32_t>(convert<std::int32_t>(a.values)));
      break;
    case VtkType::Int64:
      xml.dataArray(a.name, a.components,
                    std::span<const std::int64_t>(convert<std::int64_t>(a.values)));
      break;
    case VtkType::Float32:
      xml.dataArray(a.name, a.components, std::span<const float>(convert<float>(a.values)));
      break;
    case VtkType::Float64:
      xml.dataArray(a.name, a.components, std::span<const double>(a.values));
      break;
  }
}

}  // namespace

void writeMeshVtu(const std::filesystem::path& path, const core::TetMesh& mesh,
                  const VtuMeshOptions& options, const core::Progress& progress) {
  const std::string file = "VTU file '" + path.string() + "'";
  validate(options.pointData, mesh.vertexCount(), "point", file);
  validate(options.cellData, mesh.tetCount(), "cell", file);
  if (!options.activeTensors.empty()) {
    bool found = false;
    for (const auto& a : options.pointData) found = found || a.name == options.activeTensors;
    if (!found) {
      throw core::Error(file + ": active tensor array '" + options.activeTensors +
                        "' is not among the point arrays");
    }
  }
  progress.throwIfCancelled();

  VtkXmlWriter xml(options.encoding);
  xml.begin("VTKFile", {{"type", "UnstructuredGrid"},
                        {"version", "1.0"},
                        {"byte_order", "LittleEndian"},
                        {"header_type", "UInt64"}});
  xml.begin("UnstructuredGrid");
  xml.begin("Piece", {{"NumberOfPoints", std::to_string(mesh.vertexCount())},
                      {"NumberOfCells", std::to_string(mesh.tetCount())}});
  VtkXmlWriter::Attributes pointAttributes;
  if (!options.activeTensors.empty()) pointAttributes.push_back({"Tensors", options.activeTensors});
  xml.begin("PointData", pointAttributes);
  for (const auto& a : options.pointData) {
    const bool tensor = a.name == options.activeTensors ||
                        std::find(options.tensorArrays.begin(), options.tensorArrays.end(),
                                  a.name) != options.tensorArrays.end();
    if (tensor && a.components == 6 && a.type == VtkType::Float64) {
      xml.dataArray(a.name, 6, std::span<const double>(a.values),
                    {{"ComponentName0", "XX"},
                     {"ComponentName1", "YY"},
                     {"ComponentName2", "ZZ"},
                     {"ComponentName3", "XY"},
                     {"ComponentName4", "YZ"},
                     {"ComponentName5", "XZ"}});
    } else {
      writeArray(xml, a);
    }
  }
  xml.end();
  xml.begin("CellData");
  for (const auto& a : options.cellData) writeArray(xml, a);
  xml.end();
  progress.throwIfCancelled();

  xml.begin("Points");
  std::vector<double> points;
  points.reserve(3 * mesh.vertexCount());
  for (const auto& p : mesh.positions()) points.insert(points.end(), {p.x(), p.y(), p.z()});
  xml.dataArray("Points", 3, std::span<const double>(points));
  xml.end();

  xml.begin("Cells");
  std::vector<std::int64_t> connectivity, offsets;
  connectivity.reserve(4 * mesh.tetCount());
  offsets.reserve(mesh.tetCount());
  for (const auto& t : mesh.tets()) {
    connectivity.insert(connectivity.end(), t.begin(), t.end());
    offsets.push_back(std::int64_t(connectivity.size()));
  }
  const std::vector<std::uint8_t> types(mesh.tetCount(), 10);  // VTK_TETRA
  xml.dataArray("connectivity", 1, std::span<const std::int64_t>(connectivity));
  xml.dataArray("offsets", 1, std::span<const std::int64_t>(offsets));
  xml.dataArray("types", 1, std::span<const std::uint8_t>(types));
  xml.end();
  xml.end();  // Piece
  xml.end();  // UnstructuredGrid
  progress.throwIfCancelled();
  writeAtomically(path, [&](OutputFile& out) { xml.save(out); });
  progress.report(1.0, "VTU written");
}

double glyphTensorShift(const std::vector<core::Tensor>& tensors, double margin) {
  if (!(margin > 0) || !std::isfinite(margin))
    throw core::Error("glyph tensor margin must be positive, not " + std::to_string(margin));
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (const core::Tensor& t : tensors) {
    const core::Vec3 l = core::eigenDecompose(t).values;
    smallest = std::min(smallest, l[2]);
    largest = std::max({largest, std::abs(l[0]), std::abs(l[2])});
  }
  if (tensors.empty()) return margin;
  return -smallest + margin * (largest > 0 ? largest : 1.0);
}

void writeFieldVtu(const std::filesystem::path& path, const core::TensorField& field,
                   const VtuFieldOptions& options, const core::Progress& progress) {
  if (options.tensorName.empty()) {
    throw core::Error("VTU file '" + path.string() + "': the tensor array needs a name");
  }
  const std::size_t n = field.mesh().vertexCount();
  const std::string& T = options.tensorName;
  NamedArray tensor{T, 6, std::vector<double>(6 * n), VtkType::Float64};
  NamedArray eigval{T + ".eigval", 3, {}, VtkType::Float64};
  std::array<NamedArray, 3> eigvec{NamedArray{T + ".e1", 3, {}, VtkType::Float64},
                                   NamedArray{T + ".e2", 3, {}, VtkType::Float64},
                                   NamedArray{T + ".e3", 3, {}, VtkType::Float64}};
  NamedArray type{T + ".type", 1, {}, VtkType::Int32};
  if (options.eigenvalues) eigval.values.resize(3 * n);
  if (options.eigenvectors) {
    for (auto& e : eigvec) e.values.resize(3 * n);
  }
  if (options.tensorType) type.values.resize(n);

  progress.report(0.0, "eigen-decomposition");
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t v) {
    if (progress.cancelled()) return;
    const core::Tensor& t = field.at(int(v));
    const auto c = t.components();
    std::copy(c.begin(), c.end(), tensor.values.begin() + 6 * v);
    if (options.eigenvalues || options.eigenvectors) {
      const core::EigenDecomposition e = core::eigenDecompose(t);
      if (options.eigenvalues) {
        for (int i = 0; i < 3; ++i) eigval.values[3 * v + i] = e.values[i];
      }
      if (options.eigenvectors) {
        for (int k = 0; k < 3; ++k)
          for (int i = 0; i < 3; ++i) eigvec[k].values[3 * v + i] = e.vectors(i, k);
      }
    }
    if (options.tensorType) {
      switch (core::classify(t, options.neutralTolerance)) {
        case core::TensorType::Linear:
          type.values[v] = 1;
          break;
        case core::TensorType::Planar:
          type.values[v] = -1;
          break;
        case core::TensorType::Neutral:
          type.values[v] = 0;
          break;
      }
    }
  });
  progress.throwIfCancelled();

  VtuMeshOptions mesh;
  mesh.encoding = options.encoding;
  mesh.activeTensors = T;
  mesh.pointData.push_back(std::move(tensor));
  if (options.eigenvalues) mesh.pointData.push_back(std::move(eigval));
  if (options.eigenvectors) {
    for (auto& e : eigvec) mesh.pointData.push_back(std::move(e));
  }
  if (options.tensorType) mesh.pointData.push_back(std::move(type));
  if (options.glyphTensor) {
    const double shift = glyphTensorShift(field.values(), options.glyphMargin);
    NamedArray glyph{T + ".glyph", 6, mesh.pointData[0].values, VtkType::Float64};
    for (std::size_t v = 0; v < n; ++v)
      for (int i = 0; i < 3; ++i) glyph.values[6 * v + i] += shift;
    mesh.pointData.push_back(std::move(glyph));
    mesh.activeTensors = T + ".glyph";
    mesh.tensorArrays = {T};
  }
  mesh.pointData.insert(mesh.pointData.end(), options.pointData.begin(), options.pointData.end());
  mesh.cellData = options.cellData;
  writeMeshVtu(path, field.mesh(), mesh, progress);
}

}  // namespace tfd::io
