#pragma once
// The machines of the 3D scene: one instanced glyph mapper (one draw call for every machine, a shape per
// machine type) whose arrays are updated in place at the feed rate, the wire box around the selected
// machine, the minimum on-screen size and picking by ray.
#include "widgets/view3d/Scene3D.h"

#include <vtkActor.h>
#include <vtkCubeSource.h>
#include <vtkDoubleArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <QHash>
#include <QString>

#include <cstdint>
#include <vector>

class vtkRenderer;

namespace ocu::scene3d {

class SceneMachines {
public:
    // `machines` is the renderer's list (machines as last updated); it must outlive this object.
    explicit SceneMachines(const std::vector<Machine3D>& machines);

    vtkActor* glyphActor() const { return m_actor; }
    vtkActor* selectionActor() const { return m_selectionActor; }

    // Writes the list into the glyph arrays; `sameSet` = the ids are those of the last call, in the same
    // order, so the arrays keep their layout. Machines with a non-finite pose or size are hidden (and
    // logged when their number changes).
    void update(bool sameSet);
    // The list was replaced by an empty one: no id is known until the next update().
    void forgetIds() { m_index.clear(); }
    bool visible() const { return m_actor->GetVisibility(); }

    // The machine with that id, if it is known and drawable.
    const Machine3D* find(const QString& id) const;
    // Wire box around `m`; none when null.
    void showSelection(const Machine3D* m);

    // Like the 2D map's symbols: true size when near, but never smaller on screen than a few pixels across,
    // so a 15 m truck stays a visible shape when the whole pit is in view. Called before every frame.
    void applyMinimumSize(vtkRenderer* renderer);

    // Id of the nearest machine box hit by the segment from ray[0] to ray[1] (world), or empty.
    QString pick(const double ray[2][3]) const;

    std::uint64_t layoutCount() const { return m_layoutCount; }

private:
    void layout();
    void write(vtkIdType i, const Machine3D& m);

    const std::vector<Machine3D>& m_machines;
    vtkNew<vtkPolyData> m_data;
    vtkNew<vtkPoints> m_points;
    vtkNew<vtkDoubleArray> m_scale;
    vtkNew<vtkDoubleArray> m_rotation;
    vtkNew<vtkIntArray> m_shape;
    vtkSmartPointer<vtkUnsignedCharArray> m_colour;
    vtkNew<vtkGlyph3DMapper> m_mapper;
    vtkNew<vtkActor> m_actor;
    QHash<QString, int> m_index;
    std::uint64_t m_layoutCount = 0;
    std::size_t m_lastBad = 0;

    vtkNew<vtkCubeSource> m_selectionBox;
    vtkNew<vtkPolyDataMapper> m_selectionMapper;
    vtkNew<vtkActor> m_selectionActor;
};

} // namespace ocu::scene3d
