#!/usr/bin/env bash
# Runs an editor OpenGL test under a virtual X server (Mesa's llvmpipe gives QOpenGLWidget
# OpenGL 4.5 core). Exits 77 (ctest: skipped) with a message when Xvfb is not installed.
if ! command -v xvfb-run >/dev/null 2>&1 || ! command -v Xvfb >/dev/null 2>&1; then
  echo "SKIPPED: xvfb-run / Xvfb not installed (scripts/install-deps installs xvfb and xauth)"
  exit 77
fi
if ! command -v xauth >/dev/null 2>&1; then
  echo "SKIPPED: xauth not installed (xvfb-run needs it; scripts/install-deps installs it)"
  exit 77
fi
unset QT_QPA_PLATFORM
exec xvfb-run -a -s '-screen 0 1280x800x24' "$@"
