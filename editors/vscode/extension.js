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

// The server's commands (docs/editors.md) take the document's URI. The language client registers
// them under their own names for other extensions; these are their palette entries, run on the
// active EDS editor.
async function runOnActiveDocument(command) {
  const editor = vscode.window.activeTextEditor;
  if (!client || !editor || editor.document.languageId !== "eds") {
    vscode.window.showErrorMessage("edsconv: open an EDS file first");
    return undefined;
  }
  return client.sendRequest("workspace/executeCommand", { command, arguments: [editor.document.uri.toString()] });
}

async function showDevice() {
  const shown = await runOnActiveDocument("edsconv.showDevice");
  if (!shown) return;
  const document = await vscode.workspace.openTextDocument({ content: shown.text, language: "plaintext" });
  await vscode.window.showTextDocument(document, { viewColumn: vscode.ViewColumn.Beside, preview: true });
}

const PALETTE_COMMANDS = {
  "edsconv.showDeviceBeside": showDevice,
  "edsconv.convertActiveToXml": () => runOnActiveDocument("edsconv.convertToXml"),
  "edsconv.fixAllInActive": () => runOnActiveDocument("edsconv.fixAll"),
};

async function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand("edsconv.restartServer", restart),
    ...Object.entries(PALETTE_COMMANDS).map(([name, run]) => vscode.commands.registerCommand(name, run)),
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

module.exports = { activate, deactivate, DOCUMENT_SELECTOR, PALETTE_COMMANDS };
