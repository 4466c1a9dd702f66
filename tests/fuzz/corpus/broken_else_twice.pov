// error: 5:1: #else does not belong here
#if (0)
#else
#else
#end

