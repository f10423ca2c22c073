#include "nodes/value_codecs.h"

#include "nodes/value_types.h"

namespace tfd::nodes {

namespace {

using graph::ByteReader;
using graph::ByteWriter;
using graph::DecodeMemo;

static_assert(sizeof(core::Vec3) == 3 * sizeof(double));
static_assert(sizeof(core::Tensor) == 6 * sizeof(double));

template <class T>
void writeVec3s(ByteWriter& w, const std::vector<core::Vec3>& v) {
  w.u64(v.size());
  for (const core::Vec3& p : v) w.f64(p.x()).f64(p.y()).f64(p.z());
}

std::vector<core::Vec3> readVec3s(ByteReader& r) {
  std::vector<core::Vec3> out(r.count(24));
  for (core::Vec3& p : out) {
    const double x = r.f64(), y = r.f64(), z = r.f64();
    p = core::Vec3(x, y, z);
  }
  return out;
}

void encodeMesh(const core::TetMesh& mesh, ByteWriter& w) {
  writeVec3s<core::Vec3>(w, mesh.positions());
  w.array(mesh.tets());
  // The topology ids too: restoring them (verified) is several times faster than sorting again.
  w.array(mesh.tetEdges());
  w.array(mesh.tetFaces());
  w.array(mesh.faceTets());
}

std::shared_ptr<const core::TetMesh> decodeMesh(ByteReader& r, DecodeMemo&) {
  std::vector<core::Vec3> positions = readVec3s(r);
  std::vector<core::TetMesh::Tet> tets = r.array<core::TetMesh::Tet>();
  core::TetMesh::StoredTopology stored;
  stored.tetEdges = r.array<std::array<int, 6>>();
  stored.tetFaces = r.array<std::array<int, 4>>();
  stored.faceTets = r.array<std::array<int, 2>>();
  return std::make_shared<const core::TetMesh>(std::move(positions), std::move(tets),
                                               std::move(stored));
}

void encodeField(const core::TensorField& field, ByteWriter& w) {
  ByteWriter mesh;
  encodeMesh(field.mesh(), mesh);
  w.str(mesh.bytes());
  w.array(field.values());
}

std::shared_ptr<const core::TensorField> decodeField(ByteReader& r, DecodeMemo& memo) {
  const std::string_view meshBytes = r.bytes(r.u64(), "a mesh");
  auto mesh = memo.shared<core::TetMesh>("TetMesh", graph::checksum64(meshBytes), [&] {
    ByteReader m(meshBytes);
    std::shared_ptr<const core::TetMesh> out = decodeMesh(m, memo);
    if (!m.atEnd()) throw graph::GraphError("trailing bytes after a mesh");
    return out;
  });
  return std::make_shared<const core::TensorField>(mesh, r.array<core::Tensor>());
}

void encodeCurves(const core::DegenerateCurves& curves, ByteWriter& w) {
  w.u64(curves.size());
  for (const core::DegenerateCurve& c : curves.curves()) {
    w.i64(c.id).u8(static_cast<std::uint8_t>(c.type)).u8(c.closed ? 1 : 0);
    writeVec3s<core::Vec3>(w, c.points);
    w.array(c.patterns);
    writeVec3s<core::Vec3>(w, c.tangents);
    writeVec3s<core::Vec3>(w, c.eigenvectors);
    w.array(c.sources);
  }
  w.u64(curves.warnings().size());
  for (const std::string& s : curves.warnings()) w.str(s);
  w.pod(curves.diagnostics());
}

std::shared_ptr<const core::DegenerateCurves> decodeCurves(ByteReader& r, DecodeMemo&) {
  std::vector<core::DegenerateCurve> curves(r.count(8));
  for (core::DegenerateCurve& c : curves) {
    c.id = static_cast<int>(r.i64());
    const std::uint8_t type = r.u8();
    if (type > 1) throw graph::GraphError("bad curve type");
    c.type = static_cast<core::DegenerateType>(type);
    c.closed = r.u8() != 0;
    c.points = readVec3s(r);
    c.patterns = r.array<core::DegeneratePattern>();
    for (core::DegeneratePattern p : c.patterns)
      if (static_cast<unsigned>(p) > 2) throw graph::GraphError("bad curve pattern");
    c.tangents = readVec3s(r);
    c.eigenvectors = readVec3s(r);
    c.sources = r.array<core::PointSource>();
    for (const core::PointSource& source : c.sources)
      if (static_cast<unsigned>(source.kind) > 3) throw graph::GraphError("bad point source");
  }
  std::vector<std::string> warnings(r.count(8));
  for (std::string& s : warnings) s = r.str();
  const auto diagnostics = r.pod<core::ExtractionDiagnostics>();
  return std::make_shared<const core::DegenerateCurves>(std::move(curves), std::move(warnings),
                                                        diagnostics);
}

}  // namespace

const graph::ValueCodecs& valueCodecs() {
  static const graph::ValueCodecs table = [] {
    graph::ValueCodecs t;
    t.add<core::TetMesh>(encodeMesh, decodeMesh);
    t.add<core::TensorField>(encodeField, decodeField);
    t.add<core::DegenerateCurves>(encodeCurves, decodeCurves);
    return t;
  }();
  return table;
}

}  // namespace tfd::nodes
