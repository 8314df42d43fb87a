#pragma once
// Headings, text and tables down the pages of a PDF report (the shift report, the coverage report): a new
// page whenever the next piece does not fit.
#include <QString>
#include <QStringList>
#include <QVector>

class QPainter;
class QPdfWriter;

namespace ocu {

class PdfPageWriter {
public:
    // bodyPointSize: the font size restored after each heading.
    PdfPageWriter(QPdfWriter& pdf, QPainter& p, double bodyPointSize);
    int width() const { return m_width; }
    int& y() { return m_y; } // where the next piece goes (device units from the page's top)
    void need(int height);   // a new page unless `height` still fits on this one
    void heading(const QString& text, double pointSize);
    void text(const QString& text); // word-wrapped to the page's width

    struct TableStyle {
        int padding = 4;              // device units left and right of a cell's text
        bool ruleUnderHeader = false; // a grey line under the header row
        bool boldLastRow = false;     // e.g. a total
    };
    // Column widths as fractions of the page; the first column left-aligned, the others right; rows shaded
    // alternately.
    void table(const QStringList& header, const QVector<QStringList>& rows, const QVector<double>& widths,
               const TableStyle& style);

private:
    QPdfWriter& m_pdf;
    QPainter& m_p;
    double m_bodyPointSize;
    int m_width = 0, m_height = 0, m_y = 0;
};

} // namespace ocu
