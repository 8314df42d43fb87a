#pragma once
// One status-bar indicator per protocol link: a coloured lamp, the state in words and the data age.
#include <QElapsedTimer>
#include <QWidget>

class QLabel;

namespace ocu {

class LinkIndicator : public QWidget {
    Q_OBJECT
public:
    enum class State { NotConfigured, Up, Degraded, Down };
    Q_ENUM(State)

    explicit LinkIndicator(const QString& protocolName, QWidget* parent = nullptr);

    State state() const { return m_state; }
    QString text() const;
    // Data age is counted from the last call to dataReceived() (or given explicitly).
    void setState(State state, const QString& detail = {});
    void dataReceived();
    void setDataAgeMs(qint64 ageMs);
    qint64 dataAgeMs() const;

private:
    void refresh();
    QString m_protocol;
    State m_state = State::NotConfigured;
    QString m_detail;
    QElapsedTimer m_sinceData;
    qint64 m_ageOffsetMs = -1;
    QLabel* m_lamp;
    QLabel* m_label;
};

} // namespace ocu
