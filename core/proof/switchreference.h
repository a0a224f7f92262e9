#pragma once

#include <QCoreApplication>
#include <QObject>

#include <functional>
#include <optional>

namespace stepcom {

class ProofDrive;
struct StepMoveResult;

// Where the count stands when the carriage reaches the home switch, found as a machinist finds
// an edge: toward the switch until it reads ON, back off in coarse steps until it reads OFF,
// then creep back in single moves of the position register's resolution, reading the input
// after each, until it reads ON again. Given where it was found last, it goes to just before
// that and creeps from there. The last approach is always toward the switch (the
// negative direction) after a move away, so backlash and the switch's hysteresis are the same
// every time and only count differences matter, whether homing zeroes the count or not.
class SwitchReference : public QObject
{
    Q_OBJECT
public:
    struct Result
    {
        bool found = false;
        double position = 0; // the count where the switch came ON, distance units
        int moves = 0;
        QString error; // why it was not found (a halt, a read, the switch not seen)
    };

    // Coarse steps away from the switch and the creep toward it.
    static constexpr double kBackOff = 0.1;
    static constexpr int kMaxBackOffs = 100; // 10 mm: a switch released later is broken
    static constexpr double kSearchStep = 1; // toward a switch that is not the limit input
    static constexpr int kMaxCreeps = 200;   // 2 mm: ten times a coarse step and hysteresis
    // From a hint: this far before it, then creeps up to a coarse step before looking coarsely.
    static constexpr double kHintClearance = 0.05;
    static constexpr int kHintCreeps = 10;

    explicit SwitchReference(ProofDrive *drive, QObject *parent = nullptr);

    // How far the first approach may go toward the switch (distance units).
    void setSearch(double units) { m_search = units; }
    // `hint`: where the switch was found last, so the approach starts a little before it.
    void find(std::optional<double> hint, std::function<void(const Result &)> done);

private:
    enum class Phase { Search, BackOff, Creep };

    void step(); // reads the input, then decides
    void onInput(bool on, double position);
    void move(double units);
    void onMoved(const StepMoveResult &r);
    void fail(const QString &error);

    ProofDrive *m_drive;
    double m_search = 250;
    Phase m_phase = Phase::Search;
    double m_travelled = 0;  // toward the switch in this phase
    int m_count = 0;         // moves in this phase
    bool m_fromHint = false; // the creep started from the hint, not after a back-off
    Result m_result;
    std::function<void(const Result &)> m_done;
};

} // namespace stepcom
