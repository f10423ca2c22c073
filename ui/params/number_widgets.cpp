#include "ui/params/number_widgets.h"

#include <QSignalBlocker>

#include <cmath>
#include <limits>

namespace tfd::ui {

CompactDoubleSpinBox::CompactDoubleSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
  setDecimals(15);  // no rounding of stored values; text is formatted by textFromValue
  setRange(-1e12, 1e12);
  setKeyboardTracking(false);
  setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
  setAccelerated(true);
}

QString CompactDoubleSpinBox::textFromValue(double value) const {
  return QString::number(value, 'g', 10);
}

double CompactDoubleSpinBox::valueFromText(const QString& text) const {
  bool ok = false;
  const double v = text.trimmed().toDouble(&ok);
  return ok ? v : value();
}

QValidator::State CompactDoubleSpinBox::validate(QString& text, int&) const {
  const QString t = text.trimmed();
  if (t.isEmpty() || t == "-" || t == "+" || t.endsWith('e') || t.endsWith('E') ||
      t.endsWith("e-") || t.endsWith("e+") || t == ".")
    return QValidator::Intermediate;
  bool ok = false;
  const double v = t.toDouble(&ok);
  if (!ok) return QValidator::Invalid;
  return v >= minimum() && v <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
}

void CompactDoubleSpinBox::fixup(QString& text) const { text = textFromValue(value()); }

bool wantsLogSlider(double min, double max) { return min > 0 && max / min >= 1e3; }

RangeSlider::RangeSlider(double min, double max, bool logarithmic, QWidget* parent)
    : QSlider(Qt::Horizontal, parent), min_(min), max_(max), log_(logarithmic) {
  setRange(0, 1000);
}

double RangeSlider::valueAsDouble() const {
  const double t = value() / 1000.0;
  return log_ ? std::exp(std::log(min_) + t * (std::log(max_) - std::log(min_)))
              : min_ + t * (max_ - min_);
}

void RangeSlider::showValue(double v) {
  double t =
      log_ ? (std::log(std::max(v, min_)) - std::log(min_)) / (std::log(max_) - std::log(min_))
           : (v - min_) / (max_ - min_);
  if (!std::isfinite(t)) t = 0;
  const QSignalBlocker block(this);
  setValue(static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * 1000)));
}

}  // namespace tfd::ui
