#pragma once
// Number widgets of the parameter panel: a spin box that shows doubles in their shortest form
// (1e-08, 0.02, 60000) and accepts scientific notation, and a slider mapping an int range to
// [min, max] linearly or logarithmically.
#include <QDoubleSpinBox>
#include <QSlider>

namespace tfd::ui {

class CompactDoubleSpinBox : public QDoubleSpinBox {
 public:
  explicit CompactDoubleSpinBox(QWidget* parent = nullptr);
  QString textFromValue(double value) const override;
  double valueFromText(const QString& text) const override;
  QValidator::State validate(QString& text, int& pos) const override;
  void fixup(QString& text) const override;
};

class RangeSlider : public QSlider {
 public:
  RangeSlider(double min, double max, bool logarithmic, QWidget* parent = nullptr);
  double valueAsDouble() const;
  /// Moves the handle without emitting valueChanged.
  void showValue(double v);

 private:
  double min_, max_;
  bool log_;
};

/// Whether a range is best scrubbed logarithmically (positive and spanning 3+ decades).
bool wantsLogSlider(double min, double max);

}  // namespace tfd::ui
