#pragma once
// Text over the 3D scene: the selected machine's label, anchored 1.5 m above its roof, and up to 40 name
// labels of the other machines, nearest to the camera first and never overlapping. 2D overlays, so nothing is
// drawn in VTK's translucent pass.
#include "widgets/view3d/Scene3D.h"

#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <QRectF>
#include <QString>

#include <vector>

class vtkRenderer;

namespace ocu::scene3d {

class SceneLabels {
public:
    SceneLabels();

    // The name labels, added before the scene's actors (the selected label is added last, on top).
    const std::vector<vtkSmartPointer<vtkTextActor>>& nameLabels() const { return m_nameLabels; }
    vtkTextActor* selectedLabel() const { return m_label; }

    // The selected machine's label; hidden when null.
    void showSelected(const Machine3D* m);
    // Places the name labels for the camera of `renderer`; done before every frame because the camera may
    // have moved. `selected` is the drawable selected machine (or null), `selectedId` its id (never named
    // twice), `machinesVisible` false hides them all.
    void place(vtkRenderer* renderer, const std::vector<Machine3D>& machines, const Machine3D* selected,
               const QString& selectedId, bool machinesVisible);
    // Where the name labels of the last frame are (display pixels, origin bottom-left).
    const std::vector<QRectF>& rects() const { return m_rects; }

private:
    vtkNew<vtkTextActor> m_label;
    vtkNew<vtkCoordinate> m_labelAnchor;
    std::vector<vtkSmartPointer<vtkTextActor>> m_nameLabels;
    std::vector<QRectF> m_rects;
};

} // namespace ocu::scene3d
