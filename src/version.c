/* Version of the library actually loaded, and the names of the result codes. */
#include "cc_internal.h"

#define CC__STR2(x) #x
#define CC__STR(x) CC__STR2(x)

CC_API unsigned cc_version(void) { return (unsigned)CC_VERSION; }

CC_API const char *cc_version_string(void)
{
    return CC__STR(CC_VERSION_MAJOR) "." CC__STR(CC_VERSION_MINOR) "." CC__STR(CC_VERSION_PATCH);
}

CC_API const char *cc_result_string(int code)
{
    switch (code) {
    case CC_OK: return "CC_OK / CC_MISS (0): an action succeeded; a test or sweep found no contact";
    case CC_HIT: return "CC_HIT: first contact found";
    case CC_OVERLAP: return "CC_OVERLAP: already overlapping at t = 0";
    case CC_EVENT_LIMIT: return "CC_EVENT_LIMIT: step stopped at the event cap";
    case CC_ERR_INVALID: return "CC_ERR_INVALID: invalid argument (NULL, NaN/Inf, radius or mass <= 0, t_max < 0, restitution outside [0, 1], or two immovable bodies; a world made from a 1.0 or 1.1 def also says it for a value beyond a limit and for a call from a callback)";
    case CC_ERR_NOT_FOUND: return "CC_ERR_NOT_FOUND: no such id";
    case CC_ERR_FULL: return "CC_ERR_FULL: the world is at capacity";
    case CC_ERR_MEMORY: return "CC_ERR_MEMORY: memory missing, misaligned or too small";
    case CC_ERR_VERSION: return "CC_ERR_VERSION: struct_size not understood";
    case CC_ERR_RANGE: return "CC_ERR_RANGE: a value beyond a documented limit (a capacity above 2^26, a circle too wide for the world's period, a step past what the world allows)";
    case CC_ERR_BUSY: return "CC_ERR_BUSY: the world cannot be changed from inside its own callback (act after the call that fired it returns)";
    default: return "unknown result code";
    }
}
