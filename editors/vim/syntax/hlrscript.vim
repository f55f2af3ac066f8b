" Vim syntax file
" Language:   hlrscript scene scripts (.hls)
" Reference:  runtime/LANGUAGE_SPEC.md, lang/grammar.hpp, runtime/BUILTINS.md
" The word lists below are checked against the language by tests/editors/check_keywords.py: every
" keyword and built-in must be here, and no word the language does not have.
"
" Priorities: a `syn keyword` beats a match at the same place, and of two matches the one defined
" last wins. So only reserved words (never names) are keywords; built-ins and contextual words are
" matches, defined before the matches that show a name in a binding position (named arguments,
" members, `let NAME`), which may spell a built-in.

if exists('b:current_syntax')
  finish
endif
let s:cpo_save = &cpo
set cpo&vim

syn case match
" Words are letters, digits and '_' whatever the user's 'iskeyword' says.
syn iskeyword @,48-57,_

" ---- comments, strings, numbers, operators --------------------------------------------------------

syn match hlrComment /#.*$/ contains=@Spell

" One line only: the grammar refuses a newline inside a string.
syn region hlrString start=/"/ skip=/\\./ end=/"\|$/ oneline contains=hlrEscape,hlrBadEscape,hlrInterpolation
syn match hlrEscape /\\["\\nt{}]/ contained
syn match hlrBadEscape /\\[^"\\nt{}]/ contained
" {EXPR} or {EXPR:FORMAT}; a call's `k: v` sits in parentheses, which start first and take it.
syn region hlrInterpolation matchgroup=hlrInterpDelim start=/{/ end=/}\|$/ contained oneline contains=hlrFormat,@hlrExpr
syn match hlrFormat /:[^}"]*\ze}/ contained

" 3, 0.5, 1e-7: digits first; `0..4` stays two numbers and a range.
syn match hlrNumber /\<\d\+\%(\.\d\+\)\=\%([eE][+-]\=\d\+\)\=\>/

syn match hlrOperator /\.\.\|[=!<>]=\|[<>]\|[-+*\/%]\|=/
syn match hlrDelimiter /[:,]/

" ---- reserved words (lang/grammar.hpp `reserved`) ----------------------------------------------

syn keyword hlrConditional if else
syn keyword hlrRepeat for in
syn keyword hlrStatement return draw output
syn keyword hlrInclude include
syn keyword hlrWordOperator and or not then
syn keyword hlrBoolean true false
syn keyword hlrStorage solid nextgroup=hlrSolidName skipwhite skipnl
syn keyword hlrStorage def nextgroup=hlrFunctionName skipwhite skipnl
syn keyword hlrStorage let nextgroup=hlrDefinedName skipwhite skipnl
syn keyword hlrStorage camera nextgroup=hlrCameraName skipwhite skipnl
syn keyword hlrStatement animate nextgroup=hlrFramesWord skipwhite skipnl
syn keyword hlrStatement style nextgroup=hlrStyleHidden skipwhite skipnl
syn keyword hlrStatement paper nextgroup=hlrPaperSize skipwhite skipnl
syn keyword hlrStatement at nextgroup=hlrPageWord skipwhite skipnl

" ---- expressions ------------------------------------------------------------------------------

syn match hlrCall /\<\h\w*\ze\s*(/
syn match hlrBuiltin /\<\%(abs\|acos\|adjust\|asin\|atan\|atan2\|box\|ceil\|clamp\|cone\|cos\|cross\|cube\|cylinder\)\>/
syn match hlrBuiltin /\<\%(desens\|desens_carrier\|difference\|distance\|dodecahedron\|dot\|ease\|exp\|extrude\|floor\|follow\)\>/
syn match hlrBuiltin /\<\%(group\|hatch\|heightfield\|hexahedron\|icosahedron\|identity\|import\|intersection\|lblock\|len\|lerp\|log\)\>/
syn match hlrBuiltin /\<\%(lookat\|matrix\|max\|min\|mirror\|norm\|normalize\|octahedron\|orbit\|ortho\|place\|pow\)\>/
syn match hlrBuiltin /\<\%(prism\|pyramid\|range\|rect\|regular\|revolve\|rotate\|round\|scale\|section\|sin\|smoothstep\)\>/
syn match hlrBuiltin /\<\%(sphere\|spline\|sqrt\|stairs\|str\|sweep\|tan\|tetrahedron\|torus\|track\|translate\|union\|vec\)\>/
syn match hlrConstant /\<pi\>/
" Bound before each frame is evaluated.
syn match hlrFrameVar /\<\%(frame\|frames\|t\|time\)\>/
syn match hlrMember /\.\@1<!\.\.\@!\s*\zs\h\w*/
syn match hlrNamedArg /\<\h\w*\ze\s*:/ contained

syn region hlrParens matchgroup=hlrDelimiter start=/(/ end=/)/ contains=hlrNamedArg,@hlrExpr
" Lists and comprehensions; the comprehension's for/in/if are reserved words.
syn region hlrBrackets matchgroup=hlrDelimiter start=/\[/ end=/]/ contains=@hlrExpr

syn cluster hlrExpr contains=hlrComment,hlrString,hlrNumber,hlrOperator,hlrDelimiter,hlrConditional,hlrRepeat,
      \hlrWordOperator,hlrBoolean,hlrCall,hlrBuiltin,hlrConstant,hlrFrameVar,hlrMember,hlrParens,hlrBrackets

" ---- contextual words: keywords in their clause only ---------------------------------------------

" Followed on its line by an operand (a number, a name, a string, '(' or '['): no expression puts
" two operands side by side, so there the word is the statement or clause keyword, not a name.
syn match hlrClause /\<\%(pen\|plotter\|label\|views\|view\|dimension\|from\|to\|of\|fps\)\>\ze[ \t]\+[A-Za-z0-9_"(\[]/
" dimension angle at V: angle only between dimension and at.
syn match hlrClause /\%(\<dimension\s\+\)\@<=angle\ze\s\+at\>/
" The lone orientation after `output "x.pdf"` (after `paper SIZE` too): never a useful name.
syn match hlrClause /\<\%(landscape\|portrait\)\>/
" size: in a label; inside parentheses `size:` is a named argument instead (hlrParens).
syn match hlrClause /\<size\ze\s*:/
syn match hlrFramesWord /\<frames\>/ contained
syn match hlrStyleHidden /\<hidden\>/ contained nextgroup=hlrStyleValue skipwhite skipnl
syn match hlrStyleValue /\<\%(dashed\|off\|levels\)\>/ contained
syn match hlrPaperSize /\<\w\+\>/ contained
syn match hlrPageWord /\<page\>\ze\s*(/ contained

" ---- names being bound ------------------------------------------------------------------------

syn match hlrDefinedName /\<\h\w*\>/ contained
syn match hlrCameraName /\<\h\w*\>/ contained
syn match hlrFunctionName /\<\h\w*\>/ contained nextgroup=hlrParams skipwhite
syn region hlrParams matchgroup=hlrDelimiter start=/(/ end=/)/ contained contains=hlrParam,@hlrExpr
" A parameter is the name right after '(' or ',' (or at a line's start); a default follows '='.
syn match hlrParam /\%(\%([(,]\|^\)\s*\)\@<=\h\w*\>\%(\s*(\)\@!/ contained

" plotter NAME { KEY: EXPR ... }: defined after hlrClause, so this wins where both match.
syn match hlrClause /\<plotter\>\ze\_s\+\h\w*\_s*{/ nextgroup=hlrPlotterName skipwhite skipnl
syn match hlrPlotterName /\<\h\w*\>/ contained nextgroup=hlrPlotterBody skipwhite skipnl
syn region hlrPlotterBody matchgroup=hlrDelimiter start=/{/ end=/}/ contained contains=hlrPlotterKey,@hlrExpr
syn match hlrPlotterKey /\<\h\w*\ze\s*:/ contained

" ---- solid NAME [(OPTIONS)] { vertex ID = EXPR  face ID ID ID [hole ID ...]  line ID ID } --------

syn match hlrSolidName /\<\h\w*\>/ contained nextgroup=hlrSolidOptions,hlrSolidBody skipwhite skipnl
syn region hlrSolidOptions matchgroup=hlrDelimiter start=/(/ end=/)/ contained contains=hlrNamedArg,@hlrExpr
      \ nextgroup=hlrSolidBody skipwhite skipnl
syn region hlrSolidBody matchgroup=hlrDelimiter start=/{/ end=/}/ contained
      \ contains=hlrVertexDecl,hlrFaceItem,@hlrExpr
syn keyword hlrSolidWord vertex face hole line contained
syn match hlrVertexDecl /\<vertex\_s\+\w\+/ contained contains=hlrSolidWord
" Ids run on, across lines too, up to the next item; not before '(' or an operator: `line(...)` in a
" vertex position is a call.
syn match hlrFaceItem /\<\%(face\|line\)\>\%([ \t]*[^ \t\n0-9A-Za-z_#]\)\@!\%(\_s\+\%(\<\%(vertex\|face\|line\)\>\)\@!\w\+\)*/
      \ contained contains=hlrSolidWord

" Solid, plotter and parameter bodies span lines; scripts are short, so parse from the top.
syn sync fromstart

" ---- colours ----------------------------------------------------------------------------------

hi def link hlrComment Comment
hi def link hlrString String
hi def link hlrEscape SpecialChar
hi def link hlrBadEscape Error
hi def link hlrInterpDelim Delimiter
hi def link hlrFormat Special
hi def link hlrNumber Number
hi def link hlrOperator Operator
hi def link hlrDelimiter Delimiter
hi def link hlrConditional Conditional
hi def link hlrRepeat Repeat
hi def link hlrStatement Statement
hi def link hlrInclude Include
hi def link hlrWordOperator Operator
hi def link hlrBoolean Boolean
hi def link hlrStorage StorageClass
hi def link hlrCall Function
hi def link hlrBuiltin Function
hi def link hlrConstant Constant
hi def link hlrFrameVar Special
hi def link hlrMember Identifier
hi def link hlrNamedArg Identifier
hi def link hlrClause Keyword
hi def link hlrFramesWord Keyword
hi def link hlrStyleHidden Keyword
hi def link hlrStyleValue Keyword
hi def link hlrPageWord Keyword
hi def link hlrPaperSize Constant
hi def link hlrDefinedName Identifier
hi def link hlrCameraName Type
hi def link hlrFunctionName Function
hi def link hlrParam Identifier
hi def link hlrPlotterName Type
hi def link hlrPlotterKey Identifier
hi def link hlrSolidName Type
hi def link hlrSolidWord Keyword
hi def link hlrVertexDecl Identifier
hi def link hlrFaceItem Identifier

let b:current_syntax = 'hlrscript'
let &cpo = s:cpo_save
unlet s:cpo_save
