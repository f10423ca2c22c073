// The editors of single values (bool, int, double, enum, text, file, vec3, number list) and
// the factory choosing one per declaration. Point lists: point_list_editor.cpp.
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <algorithm>

#include <climits>
#include <cmath>
#include <limits>

#include "graph/errors.h"
#include "ui/params/number_widgets.h"
#include "ui/params/param_editor.h"
#include "ui/params/point_list_editor.h"

namespace tfd::ui {

void ParamEditor::setError(const QString& message) {
  error_ = message;
  setStyleSheet(message.isEmpty() ? QString()
                                  : "QLineEdit, QPlainTextEdit { background: #5a2424; }");
  setToolTip(message);
}

QString ParamEditor::problemWith(const graph::ParamValue& value) const {
  try {
    (void)graph::checkParamValue(decl_, value);
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

namespace {

QHBoxLayout* row(QWidget* w) {
  auto* l = new QHBoxLayout(w);
  l->setContentsMargins(0, 0, 0, 0);
  l->setSpacing(4);
  return l;
}

class BoolEditor : public ParamEditor {
 public:
  BoolEditor(const graph::ParamDecl& d, QWidget* parent) : ParamEditor(d, parent) {
    box_ = new QCheckBox(this);
    row(this)->addWidget(box_);
    connect(box_, &QCheckBox::toggled, this, [this](bool on) { edit(on); });
  }
  void setValue(const graph::ParamValue& v) override {
    const QSignalBlocker b(box_);
    box_->setChecked(std::get<bool>(v));
  }

 private:
  QCheckBox* box_;
};

/// Int and double: a spin box, with a slider when the range is bounded on both sides.
class NumberEditor : public ParamEditor {
 public:
  NumberEditor(const graph::ParamDecl& d, QWidget* parent) : ParamEditor(d, parent) {
    auto* l = row(this);
    const bool isInt = d.kind == graph::ParamKind::Int;
    const double lo = d.min.value_or(isInt ? INT_MIN : -1e12);
    const double hi = d.max.value_or(isInt ? INT_MAX : 1e12);
    if (isInt) {
      auto* s = new QSpinBox(this);
      s->setRange(static_cast<int>(std::max<double>(lo, INT_MIN)),
                  static_cast<int>(std::min<double>(hi, INT_MAX)));
      s->setKeyboardTracking(false);
      s->setAccelerated(true);
      s->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
      connect(s, &QSpinBox::valueChanged, this, [this](int v) { edit(std::int64_t{v}); });
      int_ = s;
      l->addWidget(s, 1);
    } else {
      auto* s = new CompactDoubleSpinBox(this);
      s->setRange(lo, hi);
      connect(s, &QDoubleSpinBox::valueChanged, this, [this](double v) { edit(v); });
      double_ = s;
      l->addWidget(s, 1);
    }
    if (d.min && d.max && *d.max > *d.min) {
      const bool log = d.hint == graph::UiHint::LogSlider || wantsLogSlider(*d.min, *d.max);
      slider_ = new RangeSlider(*d.min, *d.max, log, this);
      l->addWidget(slider_, 2);
      // Dragging the handle is a scrub: one undo step until it is released.
      connect(slider_, &QSlider::valueChanged, this, [this] { scrub(slider_->isSliderDown()); });
      connect(slider_, &QSlider::sliderReleased, this, [this] { finish(); });
    }
  }
  void setValue(const graph::ParamValue& v) override {
    const double x = int_ ? static_cast<double>(std::get<std::int64_t>(v)) : std::get<double>(v);
    if (int_) {
      const QSignalBlocker b(int_);
      int_->setValue(static_cast<int>(std::get<std::int64_t>(v)));
    } else {
      const QSignalBlocker b(double_);
      double_->setValue(x);
    }
    if (slider_) slider_->showValue(x);
  }
  QAbstractSpinBox* spinBox() const {
    return int_ ? static_cast<QAbstractSpinBox*>(int_) : double_;
  }
  RangeSlider* slider() const { return slider_; }

 private:
  void scrub(bool continuous) {
    const double v = slider_->valueAsDouble();
    if (int_) {
      const auto i = static_cast<std::int64_t>(std::llround(v));
      const QSignalBlocker b(int_);
      int_->setValue(static_cast<int>(i));
      edit(i, continuous);
    } else {
      const QSignalBlocker b(double_);
      double_->setValue(v);
      edit(v, continuous);
    }
  }

  QSpinBox* int_ = nullptr;
  CompactDoubleSpinBox* double_ = nullptr;
  RangeSlider* slider_ = nullptr;
};

class EnumEditor : public ParamEditor {
 public:
  EnumEditor(const graph::ParamDecl& d, QWidget* parent) : ParamEditor(d, parent) {
    combo_ = new QComboBox(this);
    for (const std::string& c : d.choices) combo_->addItem(QString::fromStdString(c));
    row(this)->addWidget(combo_, 1);
    connect(combo_, &QComboBox::currentTextChanged, this,
            [this](const QString& t) { edit(t.toStdString()); });
  }
  void setValue(const graph::ParamValue& v) override {
    const QSignalBlocker b(combo_);
    combo_->setCurrentText(QString::fromStdString(std::get<std::string>(v)));
  }

 private:
  QComboBox* combo_;
};

/// Text, validated as typed against the declaration (e.g. an expression that must parse);
/// committed when editing finishes and the text is valid. File parameters add a picker.
class TextEditor : public ParamEditor {
 public:
  TextEditor(const graph::ParamDecl& d, QWidget* parent) : ParamEditor(d, parent) {
    auto* l = row(this);
    line_ = new QLineEdit(this);
    l->addWidget(line_, 1);
    connect(line_, &QLineEdit::textEdited, this,
            [this](const QString& t) { setError(problemWith(t.toStdString())); });
    connect(line_, &QLineEdit::editingFinished, this, [this] {
      const std::string t = line_->text().toStdString();
      if (problemWith(t).isEmpty()) edit(t);
    });
    if (d.isPath()) {
      auto* browse = new QToolButton(this);
      browse->setText("…");
      browse->setToolTip(d.isInputFile() ? "Choose a file to read" : "Choose where to write");
      l->addWidget(browse);
      connect(browse, &QToolButton::clicked, this, [this] { pick(); });
    }
  }
  void setValue(const graph::ParamValue& v) override {
    const QSignalBlocker b(line_);
    line_->setText(QString::fromStdString(std::get<std::string>(v)));
    setError({});
  }
  QLineEdit* line() const { return line_; }

 private:
  void pick() {
    const QString filter =
        decl().fileFilter.empty()
            ? QString("All files (*)")
            : QString::fromStdString("Files (" + decl().fileFilter + ");;All files (*)");
    const QString path =
        decl().isInputFile()
            ? QFileDialog::getOpenFileName(this, "Choose a file", line_->text(), filter)
            : QFileDialog::getSaveFileName(this, "Choose a file", line_->text(), filter);
    if (path.isEmpty()) return;
    line_->setText(path);
    edit(path.toStdString());
  }
  QLineEdit* line_;
};

class MultilineEditor : public ParamEditor {
 public:
  MultilineEditor(const graph::ParamDecl& d, QWidget* parent) : ParamEditor(d, parent) {
    text_ = new QPlainTextEdit(this);
    text_->setMaximumHeight(90);
    row(this)->addWidget(text_, 1);
    connect(text_, &QPlainTextEdit::textChanged, this, [this] {
      const std::string t = text_->toPlainText().toStdString();
      const QString problem = problemWith(t);
      setError(problem);
      if (problem.isEmpty()) edit(t, true);
    });
  }
  void setValue(const graph::ParamValue& v) override {
    const QSignalBlocker b(text_);
    const QString t = QString::fromStdString(std::get<std::string>(v));
    if (text_->toPlainText() != t) text_->setPlainText(t);
  }

 private:
  QPlainTextEdit* text_;
};

/// A list of choices (e.g. the quantities of a voxel export): one check box per choice, the
/// value lists the checked ones in declaration order.
class ChoiceSetEditor : public ParamEditor {
 public:
  ChoiceSetEditor(const graph::ParamDecl& d, QWidget* parent) : ParamEditor(d, parent) {
    auto* l = row(this);
    for (const std::string& choice : d.choices) {
      auto* box = new QCheckBox(QString::fromStdString(choice), this);
      l->addWidget(box);
      connect(box, &QCheckBox::toggled, this, [this] { commit(); });
      boxes_.push_back(box);
    }
    l->addStretch(1);
  }
  void setValue(const graph::ParamValue& v) override {
    const auto& list = std::get<std::vector<std::string>>(v);
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      const QSignalBlocker b(boxes_[i]);
      boxes_[i]->setChecked(std::find(list.begin(), list.end(), decl().choices[i]) != list.end());
    }
    setError({});
  }

 private:
  void commit() {
    std::vector<std::string> list;
    for (std::size_t i = 0; i < boxes_.size(); ++i)
      if (boxes_[i]->isChecked()) list.push_back(decl().choices[i]);
    const QString problem = problemWith(list);
    setError(problem);
    if (problem.isEmpty()) edit(std::move(list));
  }
  std::vector<QCheckBox*> boxes_;
};

/// vec3 and fixed-size number lists: one spin box per component.
class ComponentsEditor : public ParamEditor {
 public:
  ComponentsEditor(const graph::ParamDecl& d, std::size_t count, QWidget* parent)
      : ParamEditor(d, parent) {
    auto* l = row(this);
    for (std::size_t i = 0; i < count; ++i) {
      auto* s = new CompactDoubleSpinBox(this);
      s->setRange(d.min.value_or(-1e12), d.max.value_or(1e12));
      if (d.hint == graph::UiHint::Angle) s->setSuffix("°");
      if (d.kind == graph::ParamKind::Vec3) s->setPrefix(QString("xyz"[i]) + " ");
      s->setMinimumWidth(60);
      connect(s, &QDoubleSpinBox::valueChanged, this, [this] { commit(); });
      boxes_.push_back(s);
      l->addWidget(s, 1);
    }
  }
  void setValue(const graph::ParamValue& v) override {
    std::vector<double> c;
    if (auto* p = std::get_if<graph::Vec3Param>(&v)) c.assign(p->begin(), p->end());
    if (auto* p = std::get_if<std::vector<double>>(&v)) c = *p;
    for (std::size_t i = 0; i < boxes_.size() && i < c.size(); ++i) {
      const QSignalBlocker b(boxes_[i]);
      boxes_[i]->setValue(c[i]);
    }
  }

 private:
  void commit() {
    if (decl().kind == graph::ParamKind::Vec3) {
      edit(graph::Vec3Param{boxes_[0]->value(), boxes_[1]->value(), boxes_[2]->value()});
    } else {
      std::vector<double> c;
      for (auto* b : boxes_) c.push_back(b->value());
      edit(c);
    }
  }
  std::vector<CompactDoubleSpinBox*> boxes_;
};

/// A number list of any length, typed as "1, 2, 3" (validated as typed).
class ListTextEditor : public ParamEditor {
 public:
  ListTextEditor(const graph::ParamDecl& d, QWidget* parent) : ParamEditor(d, parent) {
    line_ = new QLineEdit(this);
    row(this)->addWidget(line_, 1);
    connect(line_, &QLineEdit::textEdited, this, [this] { setError(parse().second); });
    connect(line_, &QLineEdit::editingFinished, this, [this] {
      auto [value, problem] = parse();
      setError(problem);
      if (problem.isEmpty()) edit(value);
    });
  }
  void setValue(const graph::ParamValue& v) override {
    const QSignalBlocker b(line_);
    QString t = QString::fromStdString(graph::formatParamValue(v));
    if (t.startsWith('[') && t.endsWith(']')) t = t.mid(1, t.size() - 2);
    line_->setText(t);
    setError({});
  }

 private:
  std::pair<graph::ParamValue, QString> parse() const {
    try {
      return {graph::paramFromText(decl(), line_->text().toStdString()), {}};
    } catch (const std::exception& e) {
      return {{}, QString::fromStdString(e.what())};
    }
  }
  QLineEdit* line_;
};

}  // namespace

std::unique_ptr<ParamEditor> makeParamEditor(const graph::ParamDecl& d, QWidget* parent) {
  using K = graph::ParamKind;
  switch (d.kind) {
    case K::Bool:
      return std::make_unique<BoolEditor>(d, parent);
    case K::Int:
    case K::Double:
      return std::make_unique<NumberEditor>(d, parent);
    case K::String:
      if (!d.choices.empty()) return std::make_unique<EnumEditor>(d, parent);
      if (d.hint == graph::UiHint::Multiline) return std::make_unique<MultilineEditor>(d, parent);
      return std::make_unique<TextEditor>(d, parent);
    case K::Vec3:
      return std::make_unique<ComponentsEditor>(d, 3, parent);
    case K::DoubleList:
      if (d.size && *d.size <= 6) return std::make_unique<ComponentsEditor>(d, *d.size, parent);
      return std::make_unique<ListTextEditor>(d, parent);
    case K::Vec3List:
      return std::make_unique<PointListEditor>(d, parent);
    case K::StringList:
      if (!d.choices.empty()) return std::make_unique<ChoiceSetEditor>(d, parent);
      return std::make_unique<ListTextEditor>(d, parent);
  }
  return std::make_unique<TextEditor>(d, parent);
}

}  // namespace tfd::ui
