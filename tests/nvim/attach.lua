-- What the Neovim harnesses share: attach `edsconv lsp` ($EDSCONV_PYTHON -m edsconv lsp) to the
-- current buffer with Neovim 0.7's vim.lsp.start_client, hand every publishDiagnostics result to
-- `on_diagnostics`, and give up (exit 3) when none came within 30 s.
return function(on_diagnostics)
  local python = assert(os.getenv("EDSCONV_PYTHON"), "EDSCONV_PYTHON is not set")
  local client = vim.lsp.start_client({
    name = "edsconv",
    cmd = { python, "-m", "edsconv", "lsp" },
    root_dir = vim.fn.getcwd(),
    handlers = {
      ["textDocument/publishDiagnostics"] = function(_, result) on_diagnostics(result) end,
    },
  })
  vim.lsp.buf_attach_client(0, client)
  vim.defer_fn(function()
    io.stderr:write("no diagnostics within 30 s\n")
    vim.cmd("cquit 3")
  end, 30000)
end
