" hlrscript scene scripts.
au BufRead,BufNewFile *.hls set filetype=hlrscript
