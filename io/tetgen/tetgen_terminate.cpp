// Work-around for a double free in TetGen 1.5.0 (Debian libtet1.5): on any failure TetGen's
// terminatetetgen(m, code) calls m->freememory() and then throws `code`; the throw unwinds
// through tetrahedralize(), whose local tetgenmesh destructor calls freememory() a second
// time on the same (not reset) pointers and the process crashes instead of reporting the
// error (known upstream: meshpy issue 21, pyvista/tetgen PR 108).
//
// libtet calls terminatetetgen through its PLT (it is an exported weak symbol), so this
// strong definition interposes it: it only throws, and the destructor frees the memory once.
// This file must not include tetgen.h (which defines the function inline).
// tetgen_mesher.cpp references kTetgenTerminateInterposed so the linker keeps this object.
class tetgenmesh;

void terminatetetgen(tetgenmesh* /*mesh*/, int code) { throw code; }

namespace tfd::io::detail {
extern const int kTetgenTerminateInterposed;
const int kTetgenTerminateInterposed = 1;
}  // namespace tfd::io::detail
