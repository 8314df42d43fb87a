#include "models/recording/RecorderTap.h"

#include "models/recording/MessageLog.h"
#include "models/recording/RecorderWriter.h"

namespace ocu::recording {

void Recorder::Tap::onDecoded(const TappedMessage& m) {
    if (m_r.m_options.messages)
        queue(m, false);
}

void Recorder::Tap::onRaw(const TappedMessage& m) {
    queue(m, true);
}

bool Recorder::Tap::wantsRaw() const {
    return m_r.m_options.raw;
}

void Recorder::Tap::queue(const TappedMessage& m, bool raw) {
    if (!m_r.m_running)
        return;
    Item it;
    it.kind = Item::Message;
    it.blob = packTapped(m.protocol, m.link, m.peer, m.type, raw, m.bytes.data(), m.bytes.size());
    m_r.push(std::move(it));
}

MessageTap* Recorder::messageTap() const {
    return m_tap.get();
}

void Recorder::recordRaw(const QString& link, const QByteArray& frame) {
    if (!m_options.raw)
        return;
    const QByteArray l = link.toUtf8();
    Item it;
    it.kind = Item::Message;
    it.blob = packTapped({}, std::string_view(l.constData(), size_t(l.size())), {}, {}, true,
                         reinterpret_cast<const std::uint8_t*>(frame.constData()), size_t(frame.size()));
    push(std::move(it));
}

} // namespace ocu::recording
