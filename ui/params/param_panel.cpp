#include "ui/params/param_panel.h"

#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QToolButton>
#include <QVBoxLayout>

namespace tfd::ui {

ParamPanel::ParamPanel(GraphDocument& document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  title_ = new QLabel(this);
  QFont f = title_->font();
  f.setBold(true);
  f.setPointSizeF(f.pointSizeF() * 1.15);
  title_->setFont(f);
  doc_ = new QLabel(this);
  doc_->setWordWrap(true);
  doc_->setStyleSheet("color: gray;");
  layout->addWidget(title_);
  layout->addWidget(doc_);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  form_ = new QWidget(scroll);
  new QFormLayout(form_);
  scroll->setWidget(form_);
  layout->addWidget(scroll, 1);
  connect(&document_, &GraphDocument::changed, this, [this](int flags) {
    const graph::Node* n = document_.graph().findNode(node_);
    if (!n || &n->decl() != decl_ || (flags & kDocumentReplaced)) {
      setNode(n ? node_ : std::string());
      return;
    }
    refresh();
  });
  setNode({});
}

ParamEditor* ParamPanel::editor(const std::string& param) const {
  auto it = editors_.find(param);
  return it == editors_.end() ? nullptr : it->second;
}

void ParamPanel::setNode(const std::string& node) {
  const graph::Node* n = document_.graph().findNode(node);
  node_ = n ? node : std::string();
  decl_ = n ? &n->decl() : nullptr;
  rebuild();
}

void ParamPanel::rebuild() {
  auto* form = static_cast<QFormLayout*>(form_->layout());
  while (form->rowCount() > 0) form->removeRow(0);
  editors_.clear();
  resets_.clear();
  if (!decl_) {
    title_->setText("No node selected");
    doc_->setText("Select a node on the canvas to edit its parameters.");
    return;
  }
  title_->setText(QString::fromStdString(node_ + "  (" + decl_->typeName() + ")"));
  doc_->setText(QString::fromStdString(decl_->doc()));
  if (decl_->params().empty()) form->addRow(new QLabel("This node type has no parameters."));
  for (const graph::ParamDecl& d : decl_->params()) {
    auto* cell = new QWidget(form_);
    auto* h = new QHBoxLayout(cell);
    h->setContentsMargins(0, 0, 0, 0);
    ParamEditor* editor = makeParamEditor(d, cell).release();
    editor->setParent(cell);
    auto* reset = new QToolButton(cell);
    reset->setText("↺");
    reset->setToolTip("Reset to the default, " +
                      QString::fromStdString(graph::formatParamValue(d.defaultValue)));
    h->addWidget(editor, 1);
    h->addWidget(reset);
    const std::string name = d.name;
    editor->onEdit = [this, editor, name](graph::ParamValue v, bool continuous) {
      if (document_.setParam(node_, name, std::move(v), continuous))
        editor->setError({});
      else
        editor->setError(QString::fromStdString(document_.lastError()));
    };
    editor->onFinish = [this] { document_.closeContinuousEdit(); };
    connect(reset, &QToolButton::clicked, this,
            [this, name] { document_.resetParam(node_, name); });
    auto* label = new QLabel(QString::fromStdString(d.displayLabel()), form_);
    const QString tip = QString::fromStdString(
        d.doc + (d.doc.empty() ? "" : "\n") + "Type: " + graph::typeLabel(d) +
        (graph::describeConstraints(d).empty() ? "" : ", " + graph::describeConstraints(d)));
    label->setToolTip(tip);
    editor->setToolTip(tip);
    form->addRow(label, cell);
    editors_[name] = editor;
    resets_[name] = reset;
  }
  refresh();
}

void ParamPanel::refresh() {
  const graph::Node* n = document_.graph().findNode(node_);
  if (!n) return;
  const auto& decls = n->decl().params();
  for (std::size_t i = 0; i < decls.size(); ++i) {
    const std::string& name = decls[i].name;
    if (ParamEditor* e = editor(name)) e->setValue(n->paramAt(i));
    if (auto it = resets_.find(name); it != resets_.end()) it->second->setVisible(n->isSet(i));
  }
}

}  // namespace tfd::ui
