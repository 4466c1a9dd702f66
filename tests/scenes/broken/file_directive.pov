// error: 3:31: for writing: it is outside the folders a scene may write to
// A write out of the output folder (out/SCENE under check) is refused.
#fopen Log "../../escape.txt" write
