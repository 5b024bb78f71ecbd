" EDS files (ISO 15745-4 Annex C.4), whatever the letter case of their extension.
autocmd BufRead,BufNewFile *.[eE][dD][sS] setfiletype eds
