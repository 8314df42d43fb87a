#pragma once
// Hand-off of control between consoles as the JAUS panels see it (AEP-4818 §6.3: Enhanced Access Control on
// the vehicle, a HandoffController on each console). The JAUS bridge fills it from the stack's reports: this
// console's own request for a vehicle another console holds (its state from the vehicle's answers), and the
// requests of other consoles the vehicle forwarded to us while we hold it (prompts the operator answers).
#include <QString>
#include <QVector>

namespace ocu {

enum class HandoffState {
    None,       // no request of ours
    Requesting, // asked, no answer yet
    Queued,     // the vehicle asked the holder; waiting for its answer
    Granted,    // the holder granted it: control requested, not yet confirmed
    Completed,  // control is ours through the hand-off (or the pre-emption)
    Denied,     // the holder said no
    TimedOut,   // the holder did not answer within the decision timeout
    Refused,    // not available, insufficient authority, or refused by the ordinary pre-emption rules
    Cancelled,  // withdrawn by this console
    Preempting, // the vehicle offers no Enhanced Access Control: control requested with our authority
    Waiting,    // the holder asks us to wait: still queued, re-asserted
};

// Another console's request the vehicle forwarded to us.
struct JausHandoffPrompt {
    int id = 0; // the vehicle's queue entry (what the answer names)
    quint16 requesterSubsystem = 0;
    QString requester; // its JAUS ID, "201.1.1"
    int authority = 0;
    QString explanation;          // its words; our consoles send "<call sign>: <reason>"
    qint64 receivedMs = 0;        // on the models' clock (models/ModelClock.h)
    double decisionTimeoutS = 60; // 0 = the vehicle never times it out
    bool waited = false;          // this console answered "wait" (the decision time started again then)
    bool operator==(const JausHandoffPrompt&) const = default;
};

struct JausHandoff {
    bool offered = false; // the vehicle offers Enhanced Access Control
    HandoffState state = HandoffState::None;
    QString reason; // the last outcome in words
    double requestTimeoutS = 5, decisionTimeoutS = 60;
    QVector<JausHandoffPrompt> prompts;
    bool operator==(const JausHandoff&) const = default;
};

// True while our request waits for an answer (it can be withdrawn).
inline bool isWaiting(HandoffState s) {
    return s == HandoffState::Requesting || s == HandoffState::Queued || s == HandoffState::Granted ||
           s == HandoffState::Preempting || s == HandoffState::Waiting;
}

// The word headless JSON and the event lines use for a state.
inline QString toText(HandoffState s) {
    switch (s) {
    case HandoffState::None:
        return QStringLiteral("none");
    case HandoffState::Requesting:
        return QStringLiteral("requesting");
    case HandoffState::Queued:
        return QStringLiteral("queued");
    case HandoffState::Granted:
        return QStringLiteral("granted");
    case HandoffState::Completed:
        return QStringLiteral("completed");
    case HandoffState::Denied:
        return QStringLiteral("denied");
    case HandoffState::TimedOut:
        return QStringLiteral("timed out");
    case HandoffState::Refused:
        return QStringLiteral("refused");
    case HandoffState::Cancelled:
        return QStringLiteral("cancelled");
    case HandoffState::Preempting:
        return QStringLiteral("pre-empting");
    case HandoffState::Waiting:
        return QStringLiteral("waiting");
    }
    return QStringLiteral("none");
}

} // namespace ocu
