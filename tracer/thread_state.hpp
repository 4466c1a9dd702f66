// What one thread carries between rays: its mailbox and its counters.
#pragma once

#include "tracer/counters.hpp"
#include "tracer/mailbox.hpp"

namespace hexant::tracer {

struct ThreadState {
    Mailbox mailbox;
    Counters counters;
};

}  // namespace hexant::tracer
