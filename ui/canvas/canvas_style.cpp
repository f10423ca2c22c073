#include "ui/canvas/canvas_style.h"

namespace tfd::ui::style {

QColor valueTypeColour(std::string_view typeName) {
  if (typeName == "TetMesh") return {150, 150, 160};
  if (typeName == "TensorField") return {230, 120, 60};
  if (typeName == "Constraints") return {190, 110, 220};
  if (typeName == "DegenerateCurves") return {90, 200, 120};
  // Other types: a hue from the name, so new node types get stable colours without edits here.
  unsigned h = 2166136261u;
  for (char c : typeName) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  return QColor::fromHsv(static_cast<int>(h % 360), 140, 220);
}

}  // namespace tfd::ui::style
