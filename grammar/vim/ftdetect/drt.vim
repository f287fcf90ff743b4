" .drt files are drt scenes (grammar/vim/syntax/drt.vim); set, not setf, to override
" the filetype Vim itself guesses for the extension.
autocmd BufRead,BufNewFile *.drt set filetype=drt
