#include "models/PdfPageWriter.h"

#include <QPainter>
#include <QPdfWriter>

namespace ocu {

PdfPageWriter::PdfPageWriter(QPdfWriter& pdf, QPainter& p, double bodyPointSize)
    : m_pdf(pdf), m_p(p), m_bodyPointSize(bodyPointSize) {
    m_width = p.viewport().width();
    m_height = p.viewport().height();
}

void PdfPageWriter::need(int height) {
    if (m_y + height > m_height) {
        m_pdf.newPage();
        m_y = 0;
    }
}

void PdfPageWriter::heading(const QString& text, double pointSize) {
    QFont f = m_p.font();
    f.setPointSizeF(pointSize);
    f.setBold(true);
    m_p.setFont(f);
    const int h = m_p.fontMetrics().height();
    need(h * 2);
    m_p.drawText(QRect(0, m_y, m_width, h), Qt::AlignLeft | Qt::AlignVCenter, text);
    m_y += h + h / 3;
    f.setBold(false);
    f.setPointSizeF(m_bodyPointSize);
    m_p.setFont(f);
}

void PdfPageWriter::text(const QString& t) {
    const QRect r = m_p.fontMetrics().boundingRect(QRect(0, 0, m_width, 10000), Qt::TextWordWrap, t);
    need(r.height());
    m_p.drawText(QRect(0, m_y, m_width, r.height()), Qt::TextWordWrap, t);
    m_y += r.height();
}

void PdfPageWriter::table(const QStringList& header, const QVector<QStringList>& rows,
                          const QVector<double>& widths, const TableStyle& style) {
    const int h = m_p.fontMetrics().height() * 13 / 10;
    auto line = [&](const QStringList& cells, bool bold, bool shade) {
        need(h);
        if (shade)
            m_p.fillRect(QRect(0, m_y, m_width, h), QColor(0xee, 0xf2, 0xf7));
        QFont f = m_p.font();
        f.setBold(bold);
        m_p.setFont(f);
        int x = 0;
        for (int i = 0; i < cells.size() && i < widths.size(); ++i) {
            const int w = int(widths[i] * m_width);
            m_p.drawText(QRect(x + style.padding, m_y, w - 2 * style.padding, h),
                         (i == 0 ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter, cells[i]);
            x += w;
        }
        f.setBold(false);
        m_p.setFont(f);
        m_y += h;
    };
    line(header, true, true);
    if (style.ruleUnderHeader) {
        const QPen pen = m_p.pen();
        m_p.setPen(QColor(0x90, 0x90, 0x90));
        m_p.drawLine(0, m_y, m_width, m_y);
        m_p.setPen(pen);
    }
    for (int i = 0; i < rows.size(); ++i)
        line(rows[i], style.boldLastRow && i == rows.size() - 1, i % 2 == 1);
    m_y += h / 2;
}

} // namespace ocu
