" Vim syntax file for CIP Electronic Data Sheets (EDS, ISO 15745-4 Annex C.4).
" For Vim and for Neovim before 0.9, which do not take semantic tokens from a language
" server; with `edsconv lsp` in Neovim >= 0.9 the server's tokens colour the file.
" The patterns follow grammar/eds.lark's terminals (C.4.1.2, C.4.1.3).
if exists("b:current_syntax")
  finish
endif

syntax case match

" C.4.1.2.15: a comment runs from $ to the line end, outside strings.
syntax match edsComment "\$.*$" contains=edsSuppression
syntax match edsSuppression "edsconv:\s*ignore\(-file\)\=\[[^\]]*\]" contained
" C.4.1.2.4: [Section Name] at the start of a statement.
syntax match edsSection "^\s*\[[^\]]*\]"
" C.4.1.2.5: the keyword of an entry, when its = is on the same line.
syntax match edsKeyword "^\s*\zs[A-Za-z0-9_]\+\ze\s*="
" C.4.1.3.3: strings, L-prefixed for UNICODE; escapes of Table C.4.
syntax region edsString start=+L\="+ skip=+\\\\\|\\"+ end=+"+ oneline contains=edsEscape
syntax match edsEscape +\\\([\\ntvbrfa"']\|x\x\x\|u\x\x\x\x\)+ contained
" C.4.1.3.5-C.4.1.3.11: numbers, dates and times.
syntax match edsNumber "\<0[xX]\x\+\>"
syntax match edsNumber "\<0[bB][01]\+\>"
syntax match edsNumber "[-+]\=\<\d\+\(\.\d*\)\=\([eE][-+]\=\d\+\)\=\>"
syntax match edsNumber "\<\d\{1,4}-\d\{1,2}-\d\{1,4}\>"
syntax match edsNumber "\<\d\{1,2}:\d\{1,2}:\d\{1,2}\>"
" References to numbered entries in field values (ParamN, AssemN, ConnectionN ...).
syntax match edsReference "\(=\|,\|\[\)\@<=\s*\zs\(Proxy\|Proxied\)\=\(Param\|Assem\|Connection\|Enum\)\d\+\>"
syntax match edsDelimiter "[=,;{}]"

highlight default link edsComment Comment
highlight default link edsSuppression SpecialComment
highlight default link edsSection Statement
highlight default link edsKeyword Identifier
highlight default link edsString String
highlight default link edsEscape SpecialChar
highlight default link edsNumber Number
highlight default link edsReference Type
highlight default link edsDelimiter Delimiter

let b:current_syntax = "eds"
