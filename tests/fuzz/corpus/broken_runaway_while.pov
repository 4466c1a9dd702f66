// error: 4:1: ran more than 1000 times
// flags: --max-loop-iterations 1000
// (the default limit is 10^7; the test lowers it to stay fast)
#while (1)
#end

