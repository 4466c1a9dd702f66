// error: 2:2: #fopen is not supported
#fopen Log "log.txt" write

