// The VS Code side of edsconv: start `edsconv lsp` for EDS files and hand it the documents.
// Everything else (diagnostics, hover, navigation, rename, formatting, completion, code actions)
// is the server's; highlighting is the TextMate grammar in syntaxes/.
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

// Files on disk and unsaved ones only: the other schemes (git diffs, the merge editor, live
// share ...) show a second copy of a file the server already checks, and would duplicate its
// diagnostics.
const DOCUMENT_SELECTOR = [
  { scheme: "file", language: "eds" },
  { scheme: "untitled", language: "eds" },
];
const SETTING = "edsconv.server.command";

let client;

async function start() {
  const [command, ...args] = vscode.workspace.getConfiguration("edsconv").get("server.command");
  client = new LanguageClient("edsconv", "edsconv", { command, args }, { documentSelector: DOCUMENT_SELECTOR });
  try {
    await client.start();
  } catch (error) {
    vscode.window.showErrorMessage(
      `edsconv: could not start "${[command, ...args].join(" ")}" (pip install 'edsconv[lsp]'): ${error}`,
    );
  }
}

async function restart() {
  const running = client;
  client = undefined;
  if (running) {
    try {
      await running.stop();
    } catch {
      // a server that never started, or died: nothing to stop
    }
  }
  await start();
}

async function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand("edsconv.restartServer", restart),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (event.affectsConfiguration(SETTING)) return restart();
      return undefined;
    }),
  );
  await start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate, DOCUMENT_SELECTOR };
