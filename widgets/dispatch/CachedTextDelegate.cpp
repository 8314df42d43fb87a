#include "widgets/dispatch/CachedTextDelegate.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QPainter>

namespace ocu {

const QStaticText& CachedTextDelegate::layout(const QString& text, int width, const QFont& font) const {
    if (!(font == m_font)) {
        m_cache.clear();
        m_font = font;
    }
    if (m_cache.size() > kMaxCached)
        m_cache.clear();
    auto full = m_cache.constFind(text);
    if (full == m_cache.constEnd()) {
        QStaticText st(text);
        st.setTextFormat(Qt::PlainText);
        st.setPerformanceHint(QStaticText::AggressiveCaching);
        st.prepare(QTransform(), font);
        full = m_cache.insert(text, st);
    }
    if (full->size().width() <= width)
        return *full;
    const QString key = QString::number(width) + QChar(0x1f) + text;
    auto elided = m_cache.constFind(key);
    if (elided == m_cache.constEnd()) {
        QStaticText st(QFontMetrics(font).elidedText(text, Qt::ElideRight, width));
        st.setTextFormat(Qt::PlainText);
        st.setPerformanceHint(QStaticText::AggressiveCaching);
        st.prepare(QTransform(), font);
        elided = m_cache.insert(key, st);
    }
    return *elided;
}

void CachedTextDelegate::paint(QPainter* painter, const QStyleOptionViewItem& option,
                               const QModelIndex& index) const {
    QModelRoleData roles[] = {QModelRoleData(Qt::DisplayRole),    QModelRoleData(Qt::BackgroundRole),
                              QModelRoleData(Qt::ForegroundRole), QModelRoleData(Qt::TextAlignmentRole),
                              QModelRoleData(Qt::DecorationRole), QModelRoleData(Qt::CheckStateRole),
                              QModelRoleData(Qt::FontRole)};
    index.multiData(roles);
    if (roles[4].data().isValid() || roles[5].data().isValid() || roles[6].data().isValid()) {
        QStyledItemDelegate::paint(painter, option, index);
        return;
    }
    const QWidget* widget = option.widget;
    QStyle* style = widget ? widget->style() : QApplication::style();
    const bool selected = option.state & QStyle::State_Selected;
    const QPalette::ColorGroup cg = !(option.state & QStyle::State_Enabled) ? QPalette::Disabled
                                    : (option.state & QStyle::State_Active) ? QPalette::Normal
                                                                            : QPalette::Inactive;
    const QRect r = option.rect;
    if (selected)
        painter->fillRect(r, option.palette.brush(cg, QPalette::Highlight));
    else if (const QVariant bg = roles[1].data(); bg.isValid())
        painter->fillRect(r, qvariant_cast<QBrush>(bg));

    const QString text = roles[0].data().toString();
    if (!text.isEmpty()) {
        const int margin = style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, widget) + 1;
        const QRect tr = r.adjusted(margin, 0, -margin, 0);
        const QStaticText& st = layout(text, tr.width(), option.font);
        QColor pen;
        if (selected)
            pen = option.palette.color(cg, QPalette::HighlightedText);
        else if (const QVariant fg = roles[2].data(); fg.isValid())
            pen = qvariant_cast<QBrush>(fg).color();
        else
            pen = option.palette.color(cg, QPalette::Text);
        const QVariant alignData = roles[3].data();
        const Qt::Alignment align = alignData.isValid() ? Qt::Alignment(alignData.toInt())
                                                        : (option.displayAlignment | Qt::AlignVCenter);
        const QSizeF size = st.size();
        const Qt::Alignment h = QStyle::visualAlignment(option.direction, align) & Qt::AlignHorizontal_Mask;
        qreal x = tr.left();
        if (h & Qt::AlignRight)
            x = tr.right() + 1 - size.width();
        else if (h & Qt::AlignHCenter)
            x = tr.left() + (tr.width() - size.width()) / 2;
        qreal y = tr.top();
        if (align & Qt::AlignVCenter)
            y = tr.top() + (tr.height() - size.height()) / 2;
        else if (align & Qt::AlignBottom)
            y = tr.bottom() + 1 - size.height();
        // The text fits the cell (elided above): no clip, no save/restore per cell.
        painter->setPen(pen);
        painter->setFont(option.font);
        painter->drawStaticText(QPointF(x, y), st);
    }
    if (option.state & QStyle::State_HasFocus) {
        QStyleOptionFocusRect focus;
        focus.QStyleOption::operator=(option);
        focus.rect = r;
        focus.state |= QStyle::State_KeyboardFocusChange;
        focus.backgroundColor = option.palette.color(cg, selected ? QPalette::Highlight : QPalette::Base);
        style->drawPrimitive(QStyle::PE_FrameFocusRect, &focus, painter, widget);
    }
}

} // namespace ocu
