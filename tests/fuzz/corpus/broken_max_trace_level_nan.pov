// error: 3:19: max_trace_level must be a finite number
// (issue 17, the reliability cases) once: a NaN level cast to int.
global_settings { max_trace_level sqrt(-1) }

