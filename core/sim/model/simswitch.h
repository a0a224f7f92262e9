#pragma once

#include <QtGlobal>

#include <random>

namespace stepcom {

// A limit or home switch at the carriage's real position: ON when the carriage is at or beyond
// its trip point (side -1: at or below, +1: at or above). Each new approach draws a fresh trip
// point (nominal ± jitter/2, seeded); it releases `hysteresis` past the trip point on the way out.
class SimSwitch
{
public:
    explicit SimSwitch(int side = -1);

    void configure(double nominalMm, double jitterMm, double hysteresisMm, quint32 seed);
    // Where the carriage is now; the switch follows.
    void update(double carriageMm);

    bool isOn() const { return m_on; }
    double nominal() const { return m_nominal; }
    // The trip point of the current (or next) approach.
    double tripPoint() const { return m_trip; }

private:
    double draw();
    bool reached(double carriageMm) const;
    bool released(double carriageMm) const;

    int m_side;
    double m_nominal = 0;
    double m_jitter = 0;
    double m_hysteresis = 0;
    double m_trip = 0;
    double m_last = 0;
    bool m_hasLast = false;
    bool m_on = false;
    bool m_drawPending = false; // released: the next approach draws a new trip point
    std::mt19937 m_rng;
};

} // namespace stepcom
