-- Neovim as the language client of tests/test_lsp_neovim.py: attach `edsconv lsp` to the current
-- buffer, write the first diagnostics it publishes to $EDSCONV_NVIM_OUT (one per line:
-- "line:character CODE severity message", 0-based as LSP sends them) and quit.
-- Uses only what Neovim 0.7 (Debian 12) already has: vim.lsp.start_client and buf_attach_client.
local out = assert(os.getenv("EDSCONV_NVIM_OUT"), "EDSCONV_NVIM_OUT is not set")
local attach = dofile(vim.fn.fnamemodify(debug.getinfo(1, "S").source:sub(2), ":h") .. "/attach.lua")

local function write_and_quit(diagnostics)
  local lines = {}
  for _, d in ipairs(diagnostics) do
    table.insert(lines, string.format("%d:%d %s %d %s", d.range.start.line, d.range.start.character,
      d.code, d.severity, d.message))
  end
  local file = assert(io.open(out, "w"))
  file:write(table.concat(lines, "\n"), "\n")
  file:close()
  vim.cmd("qall!")
end

attach(function(result) write_and_quit(result.diagnostics) end)
