#include "ui/params/point_list_editor.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>
#include <limits>
#include <set>

namespace tfd::ui {

PointListEditor::PointListEditor(const graph::ParamDecl& d, QWidget* parent)
    : ParamEditor(d, parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  table_ = new QTableWidget(0, 3, this);
  table_->setHorizontalHeaderLabels({"x", "y", "z"});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->verticalHeader()->setDefaultSectionSize(20);
  table_->setMinimumHeight(110);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  layout->addWidget(table_);
  auto* buttons = new QHBoxLayout();
  auto* add = new QToolButton(this);
  add->setText("+");
  add->setToolTip("Add a point after the selected one");
  auto* remove = new QToolButton(this);
  remove->setText("−");
  remove->setToolTip("Remove the selected points");
  buttons->addWidget(add);
  buttons->addWidget(remove);
  buttons->addStretch();
  layout->addLayout(buttons);
  connect(add, &QToolButton::clicked, this, [this] { addRow(); });
  connect(remove, &QToolButton::clicked, this, [this] { removeSelectedRows(); });
  connect(table_, &QTableWidget::cellChanged, this, [this](int, int) {
    if (!filling_) commit(points());
  });
}

void PointListEditor::setValue(const graph::ParamValue& v) {
  const auto& list = std::get<std::vector<graph::Vec3Param>>(v);
  filling_ = true;
  table_->setRowCount(static_cast<int>(list.size()));
  for (int r = 0; r < static_cast<int>(list.size()); ++r)
    for (int c = 0; c < 3; ++c) {
      auto* item = table_->item(r, c);
      if (!item) table_->setItem(r, c, item = new QTableWidgetItem());
      item->setText(QString::number(list[r][c], 'g', 10));
    }
  filling_ = false;
  setError({});
}

std::vector<graph::Vec3Param> PointListEditor::points() const {
  std::vector<graph::Vec3Param> out(static_cast<std::size_t>(table_->rowCount()));
  for (int r = 0; r < table_->rowCount(); ++r)
    for (int c = 0; c < 3; ++c) {
      const QTableWidgetItem* item = table_->item(r, c);
      bool ok = false;
      const double v = item ? item->text().trimmed().toDouble(&ok) : 0;
      out[r][c] = ok ? v : std::numeric_limits<double>::quiet_NaN();
    }
  return out;
}

void PointListEditor::commit(std::vector<graph::Vec3Param> list) {
  for (const auto& p : list)
    for (double c : p)
      if (std::isnan(c)) {
        setError("every cell must hold a number");
        return;
      }
  const QString problem = problemWith(list);
  setError(problem);
  if (problem.isEmpty()) edit(std::move(list));
}

void PointListEditor::addRow() {
  std::vector<graph::Vec3Param> list = points();
  const int selected = table_->currentRow();
  const int after = selected >= 0 ? selected : static_cast<int>(list.size()) - 1;
  graph::Vec3Param p{0, 0, 0};
  if (after >= 0 && after + 1 < static_cast<int>(list.size())) {
    for (int c = 0; c < 3; ++c) p[c] = 0.5 * (list[after][c] + list[after + 1][c]);
  } else if (list.size() >= 2) {
    const auto& a = list[list.size() - 2];
    const auto& b = list.back();
    for (int c = 0; c < 3; ++c) p[c] = 2 * b[c] - a[c];
  } else if (!list.empty()) {
    p = list.back();
    p[0] += 0.1;
  }
  list.insert(list.begin() + (after + 1), p);
  commit(std::move(list));
}

void PointListEditor::removeSelectedRows() {
  std::set<int> rows;
  for (const QModelIndex& i : table_->selectionModel()->selectedIndexes()) rows.insert(i.row());
  if (rows.empty() && table_->currentRow() >= 0) rows.insert(table_->currentRow());
  if (rows.empty()) return;
  std::vector<graph::Vec3Param> list;
  const auto all = points();
  for (int r = 0; r < static_cast<int>(all.size()); ++r)
    if (!rows.count(r)) list.push_back(all[r]);
  commit(std::move(list));
}

}  // namespace tfd::ui
