// A scene past one of the runtime's fixed limits (how deep a function of
// clock nests, how many steps of clock one transform holds): the message
// says which; the language reports it at the place the value was made.
#pragma once

#include <stdexcept>

namespace hexant::runtime {

struct LimitError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// More pieces of time than --max-time-pieces (a condition or a string
// switching too often over the animation): one frame read alone may pass
// it (app/scene_reading.hpp).
struct TimePiecesLimit : LimitError {
    using LimitError::LimitError;
};

}  // namespace hexant::runtime
