#pragma once
// Crew messages: a bridge whose machines take text messages names its recipients here; the
// messages go through the command gate ("send_text", audited) and received ones arrive as TextMessage events.
#include <QString>
#include <QVector>

namespace ocu {

struct CrewRecipient {
    QString id;   // machine id, e.g. "osyris:3"
    QString name; // display name
};

class CrewMessaging {
public:
    virtual ~CrewMessaging() = default;
    virtual QVector<CrewRecipient> crewRecipients() const = 0;
    // Longest text a message carries, in UTF-8 bytes.
    virtual int crewMessageMaxBytes() const = 0;
};

} // namespace ocu
