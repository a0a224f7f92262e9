#include "listen/listendecoder.h"

#include "bus/bigendian.h"
#include "bus/rtuframe.h"
#include "map/registermap.h"

#include <algorithm>
#include <utility>

namespace stepcom {

namespace {

using bigendian::byteAt;
using bigendian::wordAt;

QList<bool> bitsOf(const QByteArray &b, int from, int count)
{
    QList<bool> out;
    for (int i = 0; i < count && from + i / 8 < b.size(); ++i)
        out << bool((byteAt(b, from + i / 8) >> (i % 8)) & 1);
    return out;
}

// The registers a request writes or an answer to a read carries, by protocol address.
QMap<quint16, quint16> wordsOf(const QByteArray &request, const QByteArray *answer)
{
    QMap<quint16, quint16> out;
    const int fc = byteAt(request, 1);
    const quint16 address = wordAt(request, 2);
    if (fc == 0x06) {
        out.insert(address, wordAt(request, 4));
    } else if (fc == 0x10) {
        const int count = wordAt(request, 4);
        for (int i = 0; i < count && 7 + 2 * i + 1 < request.size() - 2; ++i)
            out.insert(quint16(address + i), wordAt(request, 7 + 2 * i));
    } else if ((fc == 0x03 || fc == 0x04) && answer && !(byteAt(*answer, 1) & 0x80)) {
        const int n = byteAt(*answer, 2);
        for (int i = 0; 2 * i + 1 < n && 3 + 2 * i + 1 < answer->size() - 2; ++i)
            out.insert(quint16(address + i), wordAt(*answer, 3 + 2 * i));
    }
    return out;
}

} // namespace

ListenDecoder::ListenDecoder(const RegisterMap *map, int baud)
    : m_map(map)
    , m_baud(baud)
{}

bool ListenDecoder::canBeRequest(const QByteArray &f)
{
    if (f.size() < 8)
        return false;
    switch (byteAt(f, 1)) {
    case 0x01:
    case 0x02:
    case 0x03:
    case 0x04:
    case 0x05:
    case 0x06:
        return f.size() == 8;
    case 0x0F:
    case 0x10:
        return f.size() == 9 + byteAt(f, 6);
    default:
        return false;
    }
}

bool ListenDecoder::answers(const QByteArray &r, const QByteArray &a)
{
    if (r.size() < 8 || a.size() < 5 || r.at(0) != a.at(0))
        return false;
    const int fc = byteAt(r, 1);
    if (byteAt(a, 1) == (fc | 0x80))
        return a.size() == 5;
    if (byteAt(a, 1) != fc)
        return false;
    const int count = wordAt(r, 4);
    switch (fc) {
    case 0x01:
    case 0x02:
        return byteAt(a, 2) == (count + 7) / 8 && a.size() == 5 + byteAt(a, 2);
    case 0x03:
    case 0x04:
        return byteAt(a, 2) == 2 * count && a.size() == 5 + byteAt(a, 2);
    case 0x05:
    case 0x06:
        return a == r;
    case 0x0F:
    case 0x10:
        return a.size() == 8 && a.left(6) == r.left(6);
    default:
        return false;
    }
}

QList<HeardEvent> ListenDecoder::frame(const HeardFrame &f)
{
    QList<HeardEvent> out;
    if (f.bytes.size() < 4)
        return out;
    if (m_pending && answers(m_pending->bytes, f.bytes)) {
        const HeardFrame request = *std::exchange(m_pending, std::nullopt);
        const HeardEvent e = decode(request, &f);
        noteAnswered(e);
        out << e;
        return out;
    }
    if (canBeRequest(f.bytes)) {
        if (m_pending)
            out << unanswered(*std::exchange(m_pending, std::nullopt));
        if (f.bytes.at(0) == 0) {
            HeardEvent e = decode(f, nullptr);
            e.kind = HeardEvent::Kind::Broadcast;
            out << e;
        } else {
            m_pending = f;
        }
        return out;
    }
    // An answer whose request was lost, or came before the listening began.
    ++m_strays;
    HeardEvent e;
    e.kind = HeardEvent::Kind::Stray;
    e.ms = f.ms;
    e.requestMs = f.ms;
    e.unit = byteAt(f.bytes, 0);
    e.fc = byteAt(f.bytes, 1) & 0x7F;
    e.answer = f.bytes;
    out << e;
    return out;
}

QList<HeardEvent> ListenDecoder::idle(qint64 ms)
{
    if (m_pending && ms - m_pending->ms >= m_answerTimeoutMs)
        return {unanswered(*std::exchange(m_pending, std::nullopt))};
    return {};
}

QList<HeardEvent> ListenDecoder::finish()
{
    if (m_pending)
        return {unanswered(*std::exchange(m_pending, std::nullopt))};
    return {};
}

HeardEvent ListenDecoder::unanswered(const HeardFrame &request)
{
    HeardEvent e = decode(request, nullptr);
    DeviceStats &s = m_stats[e.unit];
    ++s.requests;
    ++s.unanswered;
    ReplayDevice &d = m_state.devices[e.unit];
    d.answering = false;
    ++d.requests;
    ++d.errors;
    d.lastError = e.text();
    d.lastErrorMs = e.ms;
    return e;
}

HeardEvent ListenDecoder::decode(const HeardFrame &request, const HeardFrame *answer) const
{
    const QByteArray &r = request.bytes;
    HeardEvent e;
    e.kind = HeardEvent::Kind::NoAnswer;
    e.ms = answer ? answer->ms : request.ms;
    e.requestMs = request.ms;
    e.unit = byteAt(r, 0);
    e.fc = byteAt(r, 1);
    e.request = r;
    e.address = wordAt(r, 2);
    e.count = (e.fc == 0x05 || e.fc == 0x06) ? 1 : wordAt(r, 4);
    if (e.fc == 0x05)
        e.coils = {wordAt(r, 4) == 0xFF00};
    else if (e.fc == 0x0F)
        e.coils = bitsOf(r, 7, e.count);
    if (answer) {
        e.answer = answer->bytes;
        e.answerMs = std::max(0.0, double(answer->ms - request.ms) -
                                       RtuFrame::charsMs(int(answer->bytes.size()), m_baud));
        if (byteAt(answer->bytes, 1) & 0x80) {
            e.kind = HeardEvent::Kind::Exception;
            e.exception = byteAt(answer->bytes, 2);
        } else if (e.fc <= 0x04) {
            e.kind = HeardEvent::Kind::Read;
            if (e.fc <= 0x02)
                e.coils = bitsOf(answer->bytes, 3, e.count);
        } else {
            e.kind = (e.fc == 0x05 || e.fc == 0x0F) ? HeardEvent::Kind::Command
                                                    : HeardEvent::Kind::Write;
        }
    }
    if (e.kind == HeardEvent::Kind::Exception)
        return e;
    if (e.fc == 0x04) {
        e.words = wordsOf(r, answer ? &answer->bytes : nullptr); // input registers: not mapped
    } else if (e.fc == 0x03 || e.fc == 0x06 || e.fc == 0x10) {
        describeWords(&e, wordsOf(r, answer ? &answer->bytes : nullptr));
    } else if ((e.fc == 0x05 || e.fc == 0x0F) && m_map) {
        for (int i = 0; i < e.coils.size(); ++i) {
            const Parameter *c = m_map->coilAt(quint16(e.address + i));
            if (!c)
                continue;
            const bool on = e.coils.at(i);
            e.values << HeardValue{c->key, on ? 1 : 0, on ? 1.0 : 0.0, QString(),
                                   on ? QStringLiteral("on") : QStringLiteral("off")};
        }
    }
    return e;
}

void ListenDecoder::describeWords(HeardEvent *e, const QMap<quint16, quint16> &words) const
{
    const QMap<quint16, quint16> known = m_state.devices.value(e->unit).words;
    QMap<quint16, quint16> loose = words;
    for (auto it = words.cbegin(); m_map && it != words.cend(); ++it) {
        const Parameter *p = m_map->holdingAt(it.key());
        if (!p || (!e->values.isEmpty() && e->values.last().key == p->key))
            continue;
        quint16 w[2] = {0, 0};
        bool whole = true;
        for (int i = 0; i < p->words && whole; ++i) {
            const quint16 at = quint16(p->address + i);
            whole = words.contains(at) || known.contains(at);
            if (whole)
                w[i] = words.contains(at) ? words.value(at) : known.value(at);
        }
        if (!whole)
            continue;
        const qint64 raw = p->decode(w);
        e->values << HeardValue{p->key, raw, p->toEngineering(raw), p->unit, p->displayRaw(raw)};
        for (int i = 0; i < p->words; ++i)
            loose.remove(quint16(p->address + i));
    }
    e->words = loose;
}

void ListenDecoder::noteAnswered(const HeardEvent &e)
{
    ++m_pairs;
    DeviceStats &s = m_stats[e.unit];
    ++s.requests;
    ++s.answered;
    s.answerMsSum += e.answerMs;
    s.answerMsMin = s.answerMsMin < 0 ? e.answerMs : std::min(s.answerMsMin, e.answerMs);
    s.answerMsMax = std::max(s.answerMsMax, e.answerMs);
    ReplayDevice &d = m_state.devices[e.unit];
    d.answering = true;
    d.lastAnswerMs = e.ms;
    ++d.requests;
    if (e.kind == HeardEvent::Kind::Exception) {
        ++s.exceptions;
        ++d.errors;
        d.lastError = e.text();
        d.lastErrorMs = e.ms;
        return;
    }
    const QMap<quint16, quint16> words = wordsOf(e.request, &e.answer);
    for (auto it = words.cbegin(); it != words.cend(); ++it) {
        d.words.insert(it.key(), it.value());
        if (e.kind == HeardEvent::Kind::Write)
            d.written.insert(it.key(), it.value());
    }
    if (e.kind == HeardEvent::Kind::Command && !e.values.isEmpty())
        d.lastCommand = e.values.first().key;
}

} // namespace stepcom
