#pragma once

namespace stepcom {

class Shooter;

// The proofs of an axis on the checklist: the guide's picture of the margin search.
namespace proofscenes {

// Motor 1 given a load that stalls above 250 rpm; the margin search from 100 to 400 rpm on
// the checklist's "keeps its steps" step, shot when it ended with its plot. The machine and
// the speed are put back afterwards.
void margin(Shooter &s);

} // namespace proofscenes
} // namespace stepcom
