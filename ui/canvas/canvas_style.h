#pragma once
// Sizes and colours of the node canvas (one place, so items and hit tests agree).
#include <QColor>

#include <string_view>

namespace tfd::ui::style {

inline constexpr double kNodeWidth = 180;
inline constexpr double kHeaderHeight = 26;
inline constexpr double kRowHeight = 18;
inline constexpr double kPortRadius = 5.5;
inline constexpr double kPortHitRadius = 10;
inline constexpr double kDisplayFlagWidth = 14;
inline constexpr double kBadgeRadius = 7;

inline QColor canvasBackground() { return {38, 40, 44}; }
inline QColor nodeBody() { return {62, 65, 72}; }
inline QColor nodeHeader() { return {82, 86, 96}; }
inline QColor nodeSelected() { return {255, 170, 40}; }
inline QColor displayFlagOn() { return {60, 150, 255}; }
inline QColor displayFlagOff() { return {70, 74, 82}; }
inline QColor errorRed() { return {225, 45, 45}; }
inline QColor warningYellow() { return {240, 200, 40}; }
inline QColor upstreamOrange() { return {190, 110, 50}; }
inline QColor cookingBlue() { return {80, 170, 255}; }
inline QColor cookedGreen() { return {80, 190, 100}; }
inline QColor textColour() { return {225, 228, 232}; }
inline QColor dimText() { return {160, 165, 172}; }
inline QColor portHighlight() { return {120, 255, 140}; }

/// A stable colour per value type (ports and links of one type share it).
QColor valueTypeColour(std::string_view typeName);

}  // namespace tfd::ui::style
