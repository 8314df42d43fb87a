#pragma once
// The vehicle's lights as a row of toggles (AEP-4818 §9.2.2): headlights, running lights, left and right
// turn signals, brake lights and the IR source of the drive camera; never the whole vehicle's visible-light
// source. Each toggle shows what the vehicle reports (ReportIlluminationState), not what was asked: a click
// sends SetLights through the command gate (audited, answered per target) and the toggle changes only when
// the vehicle's report does. A light the vehicle says it lacks is disabled; a vehicle without the
// Illumination service shows so. The vehicle is asked for each time (the teleop panel passes its own).
#include "models/jaus/JausVehicle.h"

#include <QPointer>
#include <QWidget>

#include <functional>

class QGridLayout;
class QLabel;
class QToolButton;

namespace ocu {

class JausVehicleBridge;
class CommandGate;

class IlluminationBar : public QWidget {
    Q_OBJECT
public:
    IlluminationBar(JausVehicleBridge* bridge, CommandGate* gate, std::function<quint16()> vehicle,
                    QWidget* parent = nullptr);

    QToolButton* toggle(JausLight light) const;
    // Updates from the bridge's latest view of the vehicle (also called on every vehicle update).
    void refresh();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void clicked(JausLight light);
    void arrange(); // as many toggles per row as the width takes
    JausVehicleBridge* m_bridge;
    QPointer<CommandGate> m_gate;
    std::function<quint16()> m_vehicle;
    QLabel* m_label;
    QGridLayout* m_grid = nullptr;
    int m_perRow = 0;
    QVector<QPair<JausLight, QToolButton*>> m_toggles;
};

} // namespace ocu
