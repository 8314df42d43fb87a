#include "widgets/teleop/JoystickMappingDialog.h"

#include "widgets/teleop/VirtualStick.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ocu {

namespace {
QString settingsGroup(const QString& deviceName) {
    QString key = deviceName;
    key.replace(QLatin1Char('/'), QLatin1Char('_')); // '/' would nest groups
    return QStringLiteral("teleop/joystick/") + key;
}
} // namespace

std::optional<AxisMapping> loadSavedJoystickMapping(const QString& deviceName) {
    QSettings s;
    s.beginGroup(settingsGroup(deviceName));
    if (!s.contains(QStringLiteral("forwardAxis")))
        return std::nullopt;
    AxisMapping m;
    m.forwardAxis = std::clamp(s.value(QStringLiteral("forwardAxis")).toInt(), 0, 31);
    m.turnAxis = std::clamp(s.value(QStringLiteral("turnAxis"), m.turnAxis).toInt(), 0, 31);
    m.invertForward = s.value(QStringLiteral("invertForward"), m.invertForward).toBool();
    m.invertTurn = s.value(QStringLiteral("invertTurn"), m.invertTurn).toBool();
    m.deadZone = std::clamp(s.value(QStringLiteral("deadZone"), m.deadZone).toDouble(), 0.0, 0.9);
    return m;
}

void saveJoystickMapping(const QString& deviceName, const AxisMapping& m) {
    QSettings s;
    s.beginGroup(settingsGroup(deviceName));
    s.setValue(QStringLiteral("forwardAxis"), m.forwardAxis);
    s.setValue(QStringLiteral("turnAxis"), m.turnAxis);
    s.setValue(QStringLiteral("invertForward"), m.invertForward);
    s.setValue(QStringLiteral("invertTurn"), m.invertTurn);
    s.setValue(QStringLiteral("deadZone"), m.deadZone);
}

JoystickMappingDialog::JoystickMappingDialog(InputDevice* device, QWidget* parent)
    : QDialog(parent), m_device(device), m_forward(new QComboBox(this)), m_turn(new QComboBox(this)),
      m_invertForward(new QCheckBox(tr("Invert"), this)), m_invertTurn(new QCheckBox(tr("Invert"), this)),
      m_deadZone(new QSlider(Qt::Horizontal, this)), m_deadZoneLabel(new QLabel(this)),
      m_status(new QLabel(this)), m_preview(new QLabel(this)), m_axes(new AxisDisplay(this)) {
    setWindowTitle(tr("Joystick mapping"));
    setObjectName(QStringLiteral("dialog-joystick-mapping"));
    m_forward->setObjectName(QStringLiteral("combo-forward-axis"));
    m_turn->setObjectName(QStringLiteral("combo-turn-axis"));
    m_invertForward->setObjectName(QStringLiteral("check-invert-forward"));
    m_invertTurn->setObjectName(QStringLiteral("check-invert-turn"));
    m_deadZone->setObjectName(QStringLiteral("slider-dead-zone"));
    m_deadZone->setRange(0, 90); // as the site configuration allows
    m_status->setObjectName(QStringLiteral("label-detect-status"));
    m_status->setWordWrap(true);
    m_preview->setObjectName(QStringLiteral("label-mapped-preview"));

    auto* detectForward = new QPushButton(tr("Detect…"), this);
    detectForward->setObjectName(QStringLiteral("button-detect-forward"));
    detectForward->setToolTip(tr("Then push the stick fully forward"));
    auto* detectTurn = new QPushButton(tr("Detect…"), this);
    detectTurn->setObjectName(QStringLiteral("button-detect-turn"));
    detectTurn->setToolTip(tr("Then push the stick fully right"));
    connect(detectForward, &QPushButton::clicked, this, [this] { startDetect(Detecting::Forward); });
    connect(detectTurn, &QPushButton::clicked, this, [this] { startDetect(Detecting::Turn); });

    auto row = [this](QComboBox* c, QCheckBox* i, QPushButton* d) {
        auto* h = new QHBoxLayout;
        h->addWidget(c, 1);
        h->addWidget(i);
        h->addWidget(d);
        return h;
    };
    auto* form = new QFormLayout;
    form->addRow(tr("Device"), new QLabel(device ? device->name() : tr("none"), this));
    form->addRow(tr("Forward / reverse"), row(m_forward, m_invertForward, detectForward));
    form->addRow(tr("Turn"), row(m_turn, m_invertTurn, detectTurn));
    auto* dz = new QHBoxLayout;
    dz->addWidget(m_deadZone, 1);
    dz->addWidget(m_deadZoneLabel);
    form->addRow(tr("Dead zone"), dz);

    auto* buttons = m_buttons = new QDialogButtonBox(
        QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::RestoreDefaults, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] { setMapping(AxisMapping{}); });

    auto* l = new QVBoxLayout(this);
    l->addLayout(form);
    l->addWidget(m_axes);
    l->addWidget(m_preview);
    l->addWidget(m_status);
    l->addWidget(buttons);

    for (QComboBox* c : {m_forward, m_turn})
        connect(c, &QComboBox::currentIndexChanged, this, &JoystickMappingDialog::updatePreview);
    for (QCheckBox* c : {m_invertForward, m_invertTurn})
        connect(c, &QCheckBox::toggled, this, &JoystickMappingDialog::updatePreview);
    connect(m_deadZone, &QSlider::valueChanged, this, &JoystickMappingDialog::updatePreview);

    if (device) {
        m_raw = device->rawAxes();
        connect(device, &InputDevice::rawAxesChanged, this, &JoystickMappingDialog::setRawAxes);
    }
    m_status->setText(m_raw.isEmpty() ? tr("Move the stick to see its axes.") : QString());
    setMapping(device ? device->mapping() : AxisMapping{});
}

void JoystickMappingDialog::fillAxisCombos(int axisCount) {
    for (QComboBox* c : {m_forward, m_turn}) {
        const QSignalBlocker block(c);
        while (c->count() < axisCount)
            c->addItem(tr("Axis %1").arg(c->count()), c->count());
    }
}

void JoystickMappingDialog::setMapping(const AxisMapping& m) {
    fillAxisCombos(std::max({static_cast<int>(m_raw.size()), m.forwardAxis + 1, m.turnAxis + 1, 2}));
    m_forward->setCurrentIndex(m.forwardAxis);
    m_turn->setCurrentIndex(m.turnAxis);
    m_invertForward->setChecked(m.invertForward);
    m_invertTurn->setChecked(m.invertTurn);
    m_deadZone->setValue(static_cast<int>(std::lround(m.deadZone * 100)));
    updatePreview();
}

AxisMapping JoystickMappingDialog::mapping() const {
    AxisMapping m;
    m.forwardAxis = m_forward->currentIndex();
    m.turnAxis = m_turn->currentIndex();
    m.invertForward = m_invertForward->isChecked();
    m.invertTurn = m_invertTurn->isChecked();
    m.deadZone = m_deadZone->value() / 100.0;
    return m;
}

void JoystickMappingDialog::startDetect(Detecting what) {
    m_detecting = what;
    m_rest = m_raw;
    m_status->setText(what == Detecting::Forward ? tr("Push the stick fully forward and hold it…")
                                                 : tr("Push the stick fully to the right and hold it…"));
}

void JoystickMappingDialog::setRawAxes(const QVector<double>& raw) {
    m_raw = raw;
    fillAxisCombos(static_cast<int>(raw.size()));
    if (m_detecting != Detecting::None) {
        if (auto d = detectAxis(m_rest, raw)) {
            // Forward and right must read positive after mapping (DriveAxes convention).
            QComboBox* combo = m_detecting == Detecting::Forward ? m_forward : m_turn;
            QCheckBox* invert = m_detecting == Detecting::Forward ? m_invertForward : m_invertTurn;
            combo->setCurrentIndex(d->index);
            invert->setChecked(d->negative);
            m_status->setText(tr("%1: axis %2%3 — release the stick.")
                                  .arg(m_detecting == Detecting::Forward ? tr("Forward") : tr("Turn"))
                                  .arg(d->index)
                                  .arg(d->negative ? tr(", inverted") : QString()));
            m_detecting = Detecting::None;
        }
    }
    updatePreview();
}

void JoystickMappingDialog::updatePreview() {
    const AxisMapping m = mapping();
    const DriveAxes a = mapAxes(m_raw, m);
    m_deadZoneLabel->setText(tr("%1 %").arg(m_deadZone->value()));
    m_axes->setAxes(m_raw);
    m_axes->setMapped(a);
    m_preview->setText(tr("Demand: forward %1 %, turn %2 %")
                           .arg(std::lround(a.forward * 100))
                           .arg(std::lround(a.turn * 100)));
    // One axis cannot drive both (the site configuration refuses it too).
    const bool sameAxis = m.forwardAxis == m.turnAxis;
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(!sameAxis);
    if (sameAxis)
        m_status->setText(tr("Forward and turn need two different axes."));
    else if (m_status->text() == tr("Forward and turn need two different axes."))
        m_status->clear();
}

} // namespace ocu
