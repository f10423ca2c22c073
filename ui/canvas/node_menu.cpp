#include "ui/canvas/node_menu.h"

#include <QHeaderView>
#include <QKeyEvent>
#include <QLineEdit>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cctype>

namespace tfd::ui {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string categoryOf(const graph::NodeType& t) {
  return t.decl().category().empty() ? "Other" : t.decl().category();
}

bool takesLink(const graph::NodeType& t, const LinkStart& link) {
  const auto& ports = link.isOutput ? t.decl().inputs() : t.decl().outputs();
  return std::any_of(ports.begin(), ports.end(),
                     [&](const graph::PortDecl& p) { return p.type == link.type; });
}

}  // namespace

std::vector<const graph::NodeType*> matchingNodeTypes(const graph::NodeRegistry& registry,
                                                      std::string_view text,
                                                      const LinkStart* link) {
  const std::string needle = lower(text);
  std::vector<const graph::NodeType*> out;
  for (const graph::NodeType* t : registry.types()) {
    if (link && !takesLink(*t, *link)) continue;
    const std::string hay =
        lower(t->name()) + "\n" + lower(categoryOf(*t)) + "\n" + lower(t->decl().doc());
    if (needle.empty() || hay.find(needle) != std::string::npos) out.push_back(t);
  }
  std::stable_sort(out.begin(), out.end(), [](const graph::NodeType* a, const graph::NodeType* b) {
    return categoryOf(*a) < categoryOf(*b);
  });
  return out;
}

NodeMenu::NodeMenu(const graph::NodeRegistry& registry, QWidget* parent)
    : QFrame(parent, Qt::Popup), registry_(registry) {
  setFrameShape(QFrame::StyledPanel);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  search_ = new QLineEdit(this);
  search_->setPlaceholderText("Search node types…");
  search_->setClearButtonEnabled(true);
  tree_ = new QTreeWidget(this);
  tree_->setHeaderHidden(true);
  tree_->setRootIsDecorated(false);
  tree_->setMinimumSize(260, 320);
  layout->addWidget(search_);
  layout->addWidget(tree_);
  connect(search_, &QLineEdit::textChanged, this, [this] { rebuild(); });
  connect(search_, &QLineEdit::returnPressed, this, [this] { activateCurrent(); });
  connect(tree_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
    if (item && item->parent()) {
      tree_->setCurrentItem(item);
      activateCurrent();
    }
  });
  search_->installEventFilter(this);
  rebuild();
}

void NodeMenu::setLinkFilter(std::optional<LinkStart> link) {
  link_ = std::move(link);
  rebuild();
}

void NodeMenu::setFilterText(const QString& text) { search_->setText(text); }

void NodeMenu::rebuild() {
  tree_->clear();
  QTreeWidgetItem* group = nullptr;
  QTreeWidgetItem* first = nullptr;
  for (const graph::NodeType* t :
       matchingNodeTypes(registry_, search_->text().toStdString(), link_ ? &*link_ : nullptr)) {
    const QString category = QString::fromStdString(categoryOf(*t));
    if (!group || group->text(0) != category) {
      group = new QTreeWidgetItem(tree_, {category});
      group->setFlags(Qt::ItemIsEnabled);
      QFont f = group->font(0);
      f.setBold(true);
      group->setFont(0, f);
    }
    auto* item = new QTreeWidgetItem(group, {QString::fromStdString(t->name())});
    item->setToolTip(0, QString::fromStdString(t->decl().doc()));
    if (!first) first = item;
  }
  tree_->expandAll();
  if (first) tree_->setCurrentItem(first);
}

QStringList NodeMenu::visibleTypes() const {
  QStringList out;
  for (int g = 0; g < tree_->topLevelItemCount(); ++g)
    for (int i = 0; i < tree_->topLevelItem(g)->childCount(); ++i)
      out << tree_->topLevelItem(g)->child(i)->text(0);
  return out;
}

void NodeMenu::popupAt(QPoint globalPos) {
  search_->clear();
  rebuild();
  move(globalPos);
  show();
  search_->setFocus();
}

bool NodeMenu::activateCurrent() {
  QTreeWidgetItem* item = tree_->currentItem();
  if (!item || !item->parent()) {
    const QStringList types = visibleTypes();
    if (types.isEmpty()) return false;
    hide();
    emit typeChosen(types.front());
    return true;
  }
  const QString type = item->text(0);
  hide();
  emit typeChosen(type);
  return true;
}

bool NodeMenu::eventFilter(QObject* watched, QEvent* event) {
  // Up/Down in the search field move through the list.
  if (watched == search_ && event->type() == QEvent::KeyPress) {
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() == Qt::Key_Down || key->key() == Qt::Key_Up) {
      QTreeWidgetItem* current = tree_->currentItem();
      QTreeWidgetItem* next = current;
      do {
        next = next ? (key->key() == Qt::Key_Down ? tree_->itemBelow(next) : tree_->itemAbove(next))
                    : nullptr;
      } while (next && !next->parent());
      if (next) tree_->setCurrentItem(next);
      return true;
    }
    if (key->key() == Qt::Key_Escape) {
      hide();
      return true;
    }
  }
  return QFrame::eventFilter(watched, event);
}

}  // namespace tfd::ui
