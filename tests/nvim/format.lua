-- Neovim formats through `edsconv lsp` (tests/test_lsp_neovim.py): attach the server, wait for its
-- first diagnostics, put the cursor on line $EDSCONV_NVIM_CURSOR, then either `gggqG` with the
-- formatexpr docs/editors.md configures ($EDSCONV_NVIM_ACTION "gq") or a whole-document format
-- ("format"); write the cursor's line and then the buffer to $EDSCONV_NVIM_OUT and quit.
-- Uses only what Neovim 0.7 (Debian 12) has, and what later versions still have.
local out = assert(os.getenv("EDSCONV_NVIM_OUT"), "EDSCONV_NVIM_OUT is not set")
local attach = dofile(vim.fn.fnamemodify(debug.getinfo(1, "S").source:sub(2), ":h") .. "/attach.lua")
local action = assert(os.getenv("EDSCONV_NVIM_ACTION"), "EDSCONV_NVIM_ACTION is not set")
local cursor = tonumber(os.getenv("EDSCONV_NVIM_CURSOR") or "1")

local function format_and_quit()
  vim.api.nvim_win_set_cursor(0, { cursor, 0 })
  if action == "gq" then
    vim.bo.formatexpr = "v:lua.vim.lsp.formatexpr()"
    vim.cmd("normal! gggqG")
  elseif vim.lsp.buf.format then
    vim.lsp.buf.format({ timeout_ms = 10000 })
  else
    vim.lsp.buf.formatting_sync(nil, 10000)
  end
  local file = assert(io.open(out, "w"))
  file:write(vim.api.nvim_get_current_line(), "\n")
  file:write(table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, true), "\n"), "\n")
  file:close()
  vim.cmd("qall!")
end

local formatted = false
attach(function()
  if not formatted then
    formatted = true
    vim.schedule(format_and_quit)
  end
end)
