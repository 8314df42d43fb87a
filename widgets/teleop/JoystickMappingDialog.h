#pragma once
// The operator's joystick mapping: which raw axis drives forward and turn, their direction and the dead zone,
// with the live raw values and the resulting demand. "Detect" asks the operator to move the stick and picks
// the axis (and its direction) that moved. The dialog only edits a mapping; it never drives anything.
#include "widgets/teleop/InputDevice.h"

#include <QDialog>

#include <optional>

class QCheckBox;
class QDialogButtonBox;
class QComboBox;
class QLabel;
class QSlider;

namespace ocu {

class AxisDisplay;

// The operator's saved mapping per device name (QSettings "teleop/joystick/<name>/..."): it overrides the
// site configuration's `teleop.joystick` for that device.
std::optional<AxisMapping> loadSavedJoystickMapping(const QString& deviceName);
void saveJoystickMapping(const QString& deviceName, const AxisMapping& m);

class JoystickMappingDialog : public QDialog {
    Q_OBJECT
public:
    JoystickMappingDialog(InputDevice* device, QWidget* parent = nullptr);

    AxisMapping mapping() const;
    void setMapping(const AxisMapping& m);

public slots:
    void setRawAxes(const QVector<double>& raw);

private:
    enum class Detecting { None, Forward, Turn };
    void startDetect(Detecting what);
    void fillAxisCombos(int axisCount);
    void updatePreview();

    InputDevice* m_device;
    QComboBox* m_forward;
    QComboBox* m_turn;
    QCheckBox* m_invertForward;
    QCheckBox* m_invertTurn;
    QSlider* m_deadZone;
    QLabel* m_deadZoneLabel;
    QLabel* m_status;
    QLabel* m_preview;
    QDialogButtonBox* m_buttons = nullptr;
    AxisDisplay* m_axes;
    QVector<double> m_raw;
    Detecting m_detecting = Detecting::None;
    QVector<double> m_rest;
};

} // namespace ocu
