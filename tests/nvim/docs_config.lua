-- Run after a config from docs/editors.md (tests/test_lsp_neovim.py): wait for the diagnostics the
-- config's client receives for the current buffer, ask it for a hover on $EDSCONV_NVIM_HOVER
-- ("line:character", 0-based), write "filetype", "client name", the diagnostic codes and the hover's
-- first line to $EDSCONV_NVIM_OUT, and quit. Uses only what Neovim 0.7 has.
local out = assert(os.getenv("EDSCONV_NVIM_OUT"), "EDSCONV_NVIM_OUT is not set")
local line, character = string.match(assert(os.getenv("EDSCONV_NVIM_HOVER")), "(%d+):(%d+)")

local function report()
  local clients = vim.lsp.buf_get_clients(0)
  local names, codes = {}, {}
  for _, client in pairs(clients) do table.insert(names, client.name) end
  for _, d in ipairs(vim.diagnostic.get(0)) do table.insert(codes, d.code) end
  local params = { textDocument = vim.lsp.util.make_text_document_params(),
                   position = { line = tonumber(line), character = tonumber(character) } }
  local answers = vim.lsp.buf_request_sync(0, "textDocument/hover", params, 10000) or {}
  local hover = ""
  for _, answer in pairs(answers) do
    if answer.result then hover = vim.split(answer.result.contents.value, "\n")[1] end
  end
  local file = assert(io.open(out, "w"))
  file:write(vim.bo.filetype, "\n", table.concat(names, ","), "\n", table.concat(codes, ","), "\n", hover, "\n")
  file:close()
  vim.cmd("qall!")
end

local waited = 0
local function poll()
  if #vim.diagnostic.get(0) > 0 then return report() end
  waited = waited + 100
  if waited > 30000 then
    io.stderr:write("no diagnostics within 30 s; filetype '" .. vim.bo.filetype .. "'\n")
    return vim.cmd("cquit 3")
  end
  vim.defer_fn(poll, 100)
end
poll()
