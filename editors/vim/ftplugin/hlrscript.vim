" Vim filetype plugin: hlrscript scene scripts (.hls).
if exists('b:did_ftplugin')
  finish
endif
let b:did_ftplugin = 1

" `#` starts a comment to the end of the line; there are no block comments.
setlocal commentstring=#\ %s
setlocal comments=:#
" Let gq and auto-wrap continue comments, never code.
setlocal formatoptions-=t formatoptions+=croql

let b:undo_ftplugin = 'setlocal commentstring< comments< formatoptions<'
