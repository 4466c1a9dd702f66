// error: 4:19: #debug has printed more than 1000 bytes
// flags: --max-debug-output 1000
// (issue 45) once: a loop printing had no limit (6.5 GB of log in 60 s).
#for (I, 1, 100) #debug "twenty characters..\n" #end
