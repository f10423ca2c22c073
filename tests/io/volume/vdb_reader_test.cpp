// Reading damaged OpenVDB files (issue 15): each ends in core::Error naming the file, quickly.
#include "io/volume/vdb_reader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "core/error.h"

namespace tfd {
namespace {

// A 1375-byte file (found by fuzz_info_vdb, its grid positions then made to fit the file)
// whose tree announces about four billion root tiles. OpenVDB's RootNode::readTopology loops over
// the count without looking at the stream, so the reader spun for 30 s (over a minute under ASan)
// before failing; the reader's stream now throws at the first read past the end of the file.
TEST(VdbReader, ACountBeyondTheFileEndsAtTheEndOfTheFile) {
  const std::filesystem::path file =
      std::filesystem::path(TFD_TEST_DATA_DIR) / "damaged" / "vdb_huge_root_count.vdb";
  const auto start = std::chrono::steady_clock::now();
  try {
    io::readVdbFile(file, /*withValues=*/false);
    FAIL() << "a damaged file was read";
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("vdb_huge_root_count.vdb"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ends inside"), std::string::npos) << e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0) << "the damaged count was followed";
}

// Files (found by fuzz_info_vdb) announcing a 150 MB grid type in 734 bytes and a 2 GB
// metadata name in 10 KB. OpenVDB allocates what a string announces and copies it into its
// messages: the first kept `tfd info` busy for 9 s and printed 150 MB of spaces. Every size
// the header, metadata and grid descriptors announce is now checked against the file first.
TEST(VdbReader, SizesBeyondTheFileAreRefusedBeforeOpenVdbReadsThem) {
  // The last two (found by fuzz_info_vdb) also claim a file version newer than OpenVDB's,
  // which OpenVDB reads with its own layout: their sizes went unchecked.
  for (const char* name :
       {"vdb_huge_grid_type.vdb", "vdb_huge_metadata_name.vdb",
        "vdb_newer_version_huge_grid_name.vdb", "vdb_newer_version_huge_metadata_name.vdb"}) {
    const std::filesystem::path file = std::filesystem::path(TFD_TEST_DATA_DIR) / "damaged" / name;
    const auto start = std::chrono::steady_clock::now();
    try {
      io::readVdbFile(file, /*withValues=*/false);
      FAIL() << name << " was read";
    } catch (const core::Error& e) {
      const std::string m = e.what();
      EXPECT_LT(m.size(), 400u) << m.substr(0, 1000);
      EXPECT_NE(m.find(std::string(name) + "': the file is damaged ("), std::string::npos) << m;
      EXPECT_NE(m.find(" bytes)"), std::string::npos) << m;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 1.0) << name;
  }
}

// A 10 KB file (found by the deterministic fuzz run of CI) whose tree announces a 21 GB
// uncompressed chunk for a node buffer of 12 bytes. OpenVDB 10.0 copies the chunk into the
// buffer before comparing the sizes: `tfd info` wrote past a heap buffer (an ASan report; in a
// Release build the heap after the buffer overwritten with the file's bytes). `tfd info` now
// reads metadata only, as `vdb_print -l` does, and describes the file.
TEST(VdbReader, InfoDescribesAFileWhoseTreeWouldOverflowOpenVdb) {
  const std::filesystem::path file =
      std::filesystem::path(TFD_TEST_DATA_DIR) / "damaged" / "vdb_chunk_beyond_buffer.vdb";
  const io::VdbFileData data = io::readVdbMetadata(file);
  ASSERT_EQ(data.grids.size(), 1u);
  EXPECT_EQ(data.grids[0].name, "T.eigval");
  EXPECT_EQ(data.grids[0].valueType, "vec3s");
  EXPECT_EQ(data.fileMetadata.at("generator"), "tfd");
}

// Missing and wrong files fail with the file's name, as the full reader does.
TEST(VdbReader, MetadataOfAMissingOrForeignFileIsAnErrorNamingIt) {
  for (const char* name : {"missing.vdb", "damaged/vdb_huge_grid_type.vdb"}) {
    const std::filesystem::path file = std::filesystem::path(TFD_TEST_DATA_DIR) / name;
    try {
      io::readVdbMetadata(file);
      FAIL() << name << " was read";
    } catch (const core::Error& e) {
      EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos)
          << e.what();
    }
  }
}

// Files found by fuzz_info_vdb that kept `tfd info` busy for 4 to 44 s in a Release build:
// a transform type name of gigabytes (after checked metadata), format versions from before
// OpenVDB 2 (214, and 0; their layout is not checked), and a file without grid offsets, whose trees
// OpenVDB reads as soon as it opens it. Each is now refused at once, saying why.
TEST(VdbReader, InfoRefusesWhatItCannotCheckBeforeOpenVdbReadsIt) {
  const std::pair<const char*, const char*> cases[] = {
      {"vdb_huge_transform_type.vdb", "a grid's transform type announces"},
      {"vdb_old_version.vdb", "its format version 214 is older than OpenVDB 2"},
      {"vdb_version_zero.vdb", "its format version 0 is older than OpenVDB 2"},
      {"vdb_without_grid_offsets.vdb", "it was written as a stream"}};
  for (const auto& [name, reason] : cases) {
    const std::filesystem::path file = std::filesystem::path(TFD_TEST_DATA_DIR) / "damaged" / name;
    const auto start = std::chrono::steady_clock::now();
    try {
      io::readVdbMetadata(file);
      FAIL() << name << " was read";
    } catch (const core::Error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(std::string(name) + "': "), std::string::npos) << m;
      EXPECT_NE(m.find(reason), std::string::npos) << m;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 1.0) << name;
  }
}

}  // namespace
}  // namespace tfd
