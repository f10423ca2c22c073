#include "ui/viewport/viewport_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QToolButton>
#include <QVBoxLayout>

#include "nodes/display_values.h"
#include "ui/viewport/display_scene.h"
#include "ui/viewport/picking.h"

namespace tfd::ui {

namespace {

QToolButton* toolButton(const QString& text, const QString& tip, QWidget* parent) {
  auto* b = new QToolButton(parent);
  b->setText(text);
  b->setToolTip(tip);
  b->setAutoRaise(true);
  return b;
}

}  // namespace

ViewportPanel::ViewportPanel(GraphDocument& document, CookController& cook, QWidget* parent)
    : QWidget(parent), document_(document), cook_(cook) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  auto* bar = new QHBoxLayout;
  bar->setContentsMargins(4, 2, 4, 0);
  quantity_ = new QComboBox(this);
  quantity_->addItem("No cut", -1);
  for (auto q : {render::SliceQuantity::Mode, render::SliceQuantity::Degeneracy,
                 render::SliceQuantity::Norm})
    quantity_->addItem(QString("Cut: ") + render::toString(q), int(q));
  quantity_->setToolTip(
      "Cutting plane coloured by a quantity of the field: mode (linear red, planar blue), "
      "degeneracy (dark on degenerate curves) or the norm");
  axis_ = new QComboBox(this);
  axis_->addItems({"x", "y", "z"});
  axis_->setCurrentIndex(2);
  axis_->setToolTip("The axis the cutting plane is perpendicular to");
  position_ = new QSlider(Qt::Horizontal, this);
  position_->setRange(0, 100);
  position_->setValue(50);
  position_->setToolTip("Where the cutting plane lies along its axis");
  bar->addWidget(quantity_);
  bar->addWidget(axis_);
  bar->addWidget(position_, 1);
  view_ = new ViewportWidget(this);
  auto* frame = toolButton("Frame", "Frame the scene (F)", this);
  connect(frame, &QToolButton::clicked, view_, &ViewportWidget::frameAll);
  bar->addWidget(frame);
  for (auto [text, preset] : {std::pair{"Iso", render::ViewPreset::Iso},
                              {"X", render::ViewPreset::X},
                              {"Y", render::ViewPreset::Y},
                              {"Z", render::ViewPreset::Z}}) {
    auto* b = toolButton(text, QString("Look from ") + text, this);
    connect(b, &QToolButton::clicked, this, [this, p = preset] { view_->setView(p); });
    bar->addWidget(b);
  }
  layout->addLayout(bar);
  layout->addWidget(view_, 1);
  hint_ = new QLabel(this);
  hint_->setContentsMargins(6, 0, 6, 2);
  hint_->setStyleSheet("color: gray;");
  layout->addWidget(hint_);

  auto sliceChanged = [this] {
    axis_->setEnabled(quantity_->currentData().toInt() >= 0);
    position_->setEnabled(axis_->isEnabled());
    rebuildBase();
  };
  connect(quantity_, &QComboBox::currentIndexChanged, this, sliceChanged);
  connect(axis_, &QComboBox::currentIndexChanged, this, sliceChanged);
  connect(position_, &QSlider::valueChanged, this, sliceChanged);
  axis_->setEnabled(false);
  position_->setEnabled(false);
  connect(view_, &ViewportWidget::clicked, this, &ViewportPanel::clickAt);
  connect(&cook_, &CookController::cookFinished, this, [this](bool cancelled) {
    if (!cancelled) rebuildBase();
  });
  connect(&document_, &GraphDocument::changed, this, [this](int flags) {
    if (flags & kDocumentReplaced) {  // nothing of the previous file stays on screen
      base_ = {};
      shown_.clear();
      framedOnce_ = false;
    } else if (flags & (kUiChanged | kStructureChanged)) {
      // Another display node: drawn at once when the last cook has it, else after the next.
      const std::string node = nodes::displayNodeName(document_.graph());
      if (node != shown_ && cook_.lastGraph().findNode(node)) rebuildBase();
    }
    if (!document_.graph().findNode(selected_)) selected_.clear();
    rebuildOverlay();
  });
  updateHint();
}

std::optional<render::SliceSettings> ViewportPanel::slice() const {
  const int q = quantity_->currentData().toInt();
  if (q < 0) return std::nullopt;
  render::SliceSettings s;
  s.quantity = static_cast<render::SliceQuantity>(q);
  s.axis = axis_->currentIndex();
  s.position = position_->value() / 100.0;
  return s;
}

void ViewportPanel::setSlice(const std::optional<render::SliceSettings>& s) {
  const QSignalBlocker a(quantity_), b(axis_), c(position_);
  quantity_->setCurrentIndex(s ? quantity_->findData(int(s->quantity)) : 0);
  if (s) {
    axis_->setCurrentIndex(s->axis);
    position_->setValue(int(std::lround(s->position * 100)));
  }
  axis_->setEnabled(s.has_value());
  position_->setEnabled(s.has_value());
  rebuildBase();
}

void ViewportPanel::setSelectedNode(const std::string& node) {
  selected_ = document_.graph().findNode(node) ? node : std::string();
  rebuildOverlay();
}

void ViewportPanel::rebuildBase() {
  // The display node of the document, drawn from the last cook of it.
  const std::string node = nodes::displayNodeName(document_.graph());
  base_ = displayScene(cook_.lastGraph(), cook_.lastResult(), node, slice());
  shown_ = base_.empty() ? std::string() : node;
  const bool frame = !framedOnce_ && !base_.empty();
  framedOnce_ = framedOnce_ || frame;
  render::Scene scene = base_;
  if (const graph::Node* n = document_.graph().findNode(selected_)) addSelectionOverlay(scene, *n);
  view_->setScene(std::move(scene), frame);
  updateHint();
}

void ViewportPanel::rebuildOverlay() {
  render::Scene scene = base_;
  if (const graph::Node* n = document_.graph().findNode(selected_)) addSelectionOverlay(scene, *n);
  view_->setScene(std::move(scene));
  updateHint();
}

void ViewportPanel::updateHint() {
  QString text = shown_.empty() ? QString(
                                      "Nothing to show yet: put the display flag on a node "
                                      "and let it cook")
                                : "Showing " + QString::fromStdString(shown_);
  if (const graph::Node* n = document_.graph().findNode(selected_)) {
    const PickTarget t = pickTargetFor(*n);
    const QString name = QString::fromStdString(t.node + "." + t.param);
    if (t.kind == PickTarget::Kind::CurvePoints)
      text += "  ·  click a degenerate curve to add it to " + name;
    else if (t.kind == PickTarget::Kind::CurvePoint)
      text += "  ·  click a degenerate curve to set " + name;
    else if (t.kind == PickTarget::Kind::SpacePoints)
      text += "  ·  click to add a control point to " + name;
  }
  hint_->setText(text);
}

bool ViewportPanel::clickAt(QPointF pixel) {
  const graph::Node* n = document_.graph().findNode(selected_);
  if (!n) return false;
  const PickTarget target = pickTargetFor(*n);
  if (target.kind == PickTarget::Kind::None) return false;
  const render::Camera& cam = view_->camera();
  const int w = view_->width(), h = view_->height();
  std::optional<render::Vec3> p;
  if (target.needsCurve()) {
    p = pickCurvePoint(view_->scene().curves, cam, w, h, pixel.x(), pixel.y());
    if (!p) {
      emit message("No degenerate curve under the cursor");
      return false;
    }
  } else {
    const std::vector<render::Vec3> existing = pickedPoints(*n);
    p = pointInSpace(cam, w, h, pixel.x(), pixel.y(),
                     existing.empty() ? cam.target : existing.back());
  }
  if (!applyPick(document_, target, *p)) {
    emit message(QString::fromStdString(document_.lastError()));
    return false;
  }
  emit message(QString("Picked (%1, %2, %3) for %4.%5")
                   .arg(p->x(), 0, 'g', 4)
                   .arg(p->y(), 0, 'g', 4)
                   .arg(p->z(), 0, 'g', 4)
                   .arg(QString::fromStdString(target.node), QString::fromStdString(target.param)));
  return true;
}

}  // namespace tfd::ui
