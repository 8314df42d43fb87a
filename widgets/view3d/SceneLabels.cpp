#include "widgets/view3d/SceneLabels.h"

#include "widgets/view3d/SceneCommon.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <utility>

namespace ocu::scene3d {

namespace {

constexpr int kMaxLabels = 40; // name labels drawn at once (nearest first, never overlapping)

} // namespace

SceneLabels::SceneLabels() {
    for (int i = 0; i < kMaxLabels; ++i) {
        auto t = vtkSmartPointer<vtkTextActor>::New();
        t->GetTextProperty()->SetFontSize(12);
        t->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
        t->GetTextProperty()->SetBackgroundColor(0.12, 0.12, 0.12);
        t->GetTextProperty()->SetBackgroundOpacity(0.6);
        t->GetTextProperty()->SetJustificationToCentered();
        t->GetTextProperty()->SetVerticalJustificationToBottom();
        t->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
        t->SetVisibility(false);
        m_nameLabels.push_back(t);
    }
    m_label->GetTextProperty()->SetFontSize(16);
    m_label->GetTextProperty()->SetBold(true);
    m_label->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
    m_label->GetTextProperty()->SetBackgroundColor(0.1, 0.1, 0.1);
    m_label->GetTextProperty()->SetBackgroundOpacity(0.7);
    m_label->GetTextProperty()->SetJustificationToCentered();
    // Text sits above its anchor so it never hides the machine it names.
    m_label->GetTextProperty()->SetVerticalJustificationToBottom();
    // Anchored 1.5 m above the machine roof, then lifted 14 px on screen.
    m_labelAnchor->SetCoordinateSystemToWorld();
    m_label->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    m_label->GetPositionCoordinate()->SetReferenceCoordinate(m_labelAnchor);
    m_label->GetPositionCoordinate()->SetValue(0.0, 14.0);
    m_label->SetVisibility(false);
}

void SceneLabels::showSelected(const Machine3D* m) {
    m_label->SetVisibility(m != nullptr);
    if (m == nullptr)
        return;
    m_labelAnchor->SetValue(m->e, m->n, m->u + m->height + 1.5);
    m_label->Modified();
    const QString text = m->label.isEmpty() ? m->id : m->label;
    m_label->SetInput(text.toUtf8().constData());
}

// Nearest to the camera first, none overlapping another or the selected machine's label; at most kMaxLabels.
void SceneLabels::place(vtkRenderer* renderer, const std::vector<Machine3D>& machines,
                        const Machine3D* selected, const QString& selectedId, bool machinesVisible) {
    m_rects.clear();
    int w = 0, h = 0;
    std::size_t used = 0;
    if (windowSize(renderer, w, h) && machinesVisible) {
        vtkCamera* cam = renderer->GetActiveCamera();
        double eye[3];
        cam->GetPosition(eye);
        auto project = [&](const Machine3D& m, double& x, double& y) {
            renderer->SetWorldPoint(m.e, m.n, m.u + m.height + 1.0, 1.0);
            renderer->WorldToDisplay();
            double dp[3];
            renderer->GetDisplayPoint(dp);
            x = dp[0];
            y = dp[1];
            return dp[2] >= 0.0 && dp[2] <= 1.0 && x >= 0 && x < w && y >= 0 && y < h;
        };
        auto rectFor = [](const QString& text, double x, double y, int fontPx) {
            const double tw = text.size() * fontPx * 0.6 + 8.0, th = fontPx + 6.0;
            return QRectF(x - tw / 2.0, y + 6.0, tw, th);
        };
        if (selected != nullptr) {
            double x = 0, y = 0;
            if (project(*selected, x, y))
                m_rects.push_back(
                    rectFor(selected->label.isEmpty() ? selected->id : selected->label, x, y + 8.0, 16));
        }
        std::vector<std::pair<double, std::size_t>> order;
        order.reserve(machines.size());
        for (std::size_t i = 0; i < machines.size(); ++i) {
            const Machine3D& m = machines[i];
            if (!finite(m) || m.id == selectedId)
                continue;
            const double d2 = (m.e - eye[0]) * (m.e - eye[0]) + (m.n - eye[1]) * (m.n - eye[1]) +
                              (m.u - eye[2]) * (m.u - eye[2]);
            order.emplace_back(d2, i);
        }
        std::sort(order.begin(), order.end());
        const std::size_t first = m_rects.size();
        for (const auto& [d2, i] : order) {
            if (used == m_nameLabels.size())
                break;
            const Machine3D& m = machines[i];
            double x = 0, y = 0;
            if (!project(m, x, y))
                continue;
            const QString text = m.label.isEmpty() ? m.id : m.label;
            const QRectF r = rectFor(text, x, y, 12);
            if (std::any_of(m_rects.begin(), m_rects.end(), [&](const QRectF& o) { return o.intersects(r); }))
                continue;
            m_rects.push_back(r);
            vtkTextActor* t = m_nameLabels[used++];
            t->SetInput(text.toUtf8().constData());
            t->SetPosition(x, y + 6.0);
            t->SetVisibility(true);
        }
        // Only the name labels are reported (the selected machine's label is drawn by `m_label`).
        m_rects.erase(m_rects.begin(), m_rects.begin() + static_cast<std::ptrdiff_t>(first));
    }
    for (std::size_t k = used; k < m_nameLabels.size(); ++k)
        m_nameLabels[k]->SetVisibility(false);
}

} // namespace ocu::scene3d
