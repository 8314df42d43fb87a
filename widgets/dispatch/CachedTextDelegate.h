#pragma once
// A cell delegate for large, often-updated tables (the dispatch table with 1,000 trucks): it
// paints what QStyledItemDelegate paints for a plain text cell — background or selection, text in the
// model's alignment and foreground colour, elided at the right, the focus frame — but lays each distinct
// text out once (a QStaticText kept per text and per elision width) instead of running the style's text
// layout for every cell at every repaint, which was most of the table's paint time. Cells with an icon, a
// check box or a font of their own are left to QStyledItemDelegate. Tooltips and size hints are inherited.
#include <QFont>
#include <QHash>
#include <QStaticText>
#include <QStyledItemDelegate>

namespace ocu {

class CachedTextDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    void paint(QPainter* painter, const QStyleOptionViewItem& option,
               const QModelIndex& index) const override;

    int cachedTexts() const { return int(m_cache.size()); }
    static constexpr int kMaxCached = 8192; // distinct (text, width) layouts kept; then the cache restarts

private:
    const QStaticText& layout(const QString& text, int width, const QFont& font) const;

    mutable QHash<QString, QStaticText> m_cache; // key: text, or "<width>\x1f<text>" when elided
    mutable QFont m_font;
};

} // namespace ocu
