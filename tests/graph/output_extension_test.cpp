// Output-file parameters that declare their extensions refuse a file name of another format
// (an ExportVTU writing "x.vdb" would hide what the file holds), naming the parameter.
#include <gtest/gtest.h>

#include "graph/errors.h"
#include "graph/json_text.h"
#include "graph/paths.h"

namespace tfd::graph {
namespace {

ParamDecl outputFile(const std::string& filter) {
  ParamDecl d;
  d.name = "path";
  d.kind = ParamKind::String;
  d.hint = UiHint::OutputFile;
  d.fileFilter = filter;
  return d;
}

TEST(OutputExtension, AMatchingExtensionInAnyCaseIsAccepted) {
  EXPECT_EQ(outputExtensionProblem(outputFile("*.vtu"), "out/field.vtu"), "");
  EXPECT_EQ(outputExtensionProblem(outputFile("*.vtu"), "FIELD.VTU"), "");
  EXPECT_EQ(outputExtensionProblem(outputFile("*.json *.vtp *.obj"), "c.obj"), "");
  EXPECT_EQ(outputExtensionProblem(outputFile("*.exr"), "slices/f.%04d.exr"), "");
  EXPECT_EQ(outputExtensionProblem(outputFile("*.vtu"), ""), "") << "empty: nothing written";
}

TEST(OutputExtension, AnotherExtensionIsRefusedListingTheRightOnes) {
  EXPECT_EQ(outputExtensionProblem(outputFile("*.vtu"), "out/x.vdb"),
            "'x.vdb' does not end in .vtu, the kind of file this node writes");
  EXPECT_EQ(outputExtensionProblem(outputFile("*.json *.vtp *.obj"), "c"),
            "'c' does not end in .json, .vtp or .obj, the kind of file this node writes");
  EXPECT_NE(outputExtensionProblem(outputFile("*.vtu"), ".vtu"), "")
      << "a name, not only an extension";
}

TEST(OutputExtension, InputFilesAndFreeFiltersAreNotChecked) {
  ParamDecl in = outputFile("*.obj");
  in.hint = UiHint::InputFile;
  EXPECT_EQ(outputExtensionProblem(in, "x.stl"), "");
  EXPECT_EQ(outputExtensionProblem(outputFile(""), "x.anything"), "");
  EXPECT_EQ(outputExtensionProblem(outputFile("images (*.png)"), "x.jpg"), "");
}

TEST(LoadErrorText, ControlBytesFromTheFileAreEscaped) {
  const LoadError e("g.tfd.json", "/nodes/a\x1b", "unknown node type \"\x1b[2J\x07\"");
  EXPECT_EQ(std::string(e.what()),
            "g.tfd.json at /nodes/a\\x1b: unknown node type \"\\x1b[2J\\x07\"");
  EXPECT_EQ(e.message(), "unknown node type \"\\x1b[2J\\x07\"");
}

}  // namespace
}  // namespace tfd::graph
