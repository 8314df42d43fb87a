#pragma once
// The recorder's tap on the stacks (RecorderTap.cpp): every decoded inbound message and, with record.raw,
// every raw frame, packed and queued on the io threads that received them.
#include "models/recording/Recorder.h"
#include "protocols/common/MessageTap.h"

namespace ocu::recording {

class Recorder::Tap final : public MessageTap {
public:
    explicit Tap(Recorder& r) : m_r(r) {}
    void onDecoded(const TappedMessage& m) override;
    void onRaw(const TappedMessage& m) override;
    bool wantsRaw() const override;

private:
    // Packs and queues, nothing else (io threads never wait for the writer).
    void queue(const TappedMessage& m, bool raw);
    Recorder& m_r;
};

} // namespace ocu::recording
