// The VS Code side of edsconv: start `edsconv lsp` for EDS files and hand it the documents.
// Everything else (diagnostics, hover, navigation, rename, formatting, completion, code actions)
// is the server's; highlighting is the TextMate grammar in syntaxes/.
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

async function activate(context) {
  const [command, ...args] = vscode.workspace.getConfiguration("edsconv").get("server.command");
  client = new LanguageClient(
    "edsconv",
    "edsconv",
    { command, args },
    { documentSelector: [{ language: "eds" }] },
  );
  context.subscriptions.push(client);
  try {
    await client.start();
  } catch (error) {
    vscode.window.showErrorMessage(
      `edsconv: could not start "${[command, ...args].join(" ")}" (pip install 'edsconv[lsp]'): ${error}`,
    );
  }
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
