// extension.js with stand-ins for the vscode API and the language client: it starts the server
// command from the `edsconv.server.command` setting for "eds" documents on disk or unsaved, and
// restarts it when the setting changes or on the "restart" command.
"use strict";

const test = require("node:test");
const assert = require("node:assert");
const Module = require("node:module");
const path = require("node:path");

function loadExtension(stubs) {
  const original = Module._load;
  Module._load = function (request, parent, isMain) {
    if (request in stubs) return stubs[request];
    return original.call(this, request, parent, isMain);
  };
  try {
    const file = path.join(__dirname, "..", "extension.js");
    delete require.cache[file];
    return require(file);
  } finally {
    Module._load = original;
  }
}

function fakeVscode(settings, shown = []) {
  const commands = {};
  const listeners = [];
  return {
    commands,
    listeners,
    vscode: {
      workspace: {
        getConfiguration: (section) => ({ get: (key) => {
          assert.strictEqual(`${section}.${key}`, "edsconv.server.command");
          return settings.command;
        } }),
        onDidChangeConfiguration: (listener) => { listeners.push(listener); return { dispose() {} }; },
        openTextDocument: async (options) => options,
      },
      commands: { registerCommand: (name, run) => { commands[name] = run; return { dispose() {} }; } },
      window: {
        showErrorMessage: (message) => shown.push(message),
        activeTextEditor: settings.editor,
        showTextDocument: async (document, options) => shown.push({ document, options }),
      },
      ViewColumn: { Beside: -2 },
    },
  };
}

function fakeClient(started, stopped) {
  return class LanguageClient {
    constructor(id, name, serverOptions, clientOptions) {
      Object.assign(this, { id, name, serverOptions, clientOptions });
    }
    async start() { started.push(this); }
    async stop() { stopped.push(this); }
    dispose() {}
  };
}

test("activate starts the configured server for EDS files on disk and unsaved ones only", async () => {
  const started = [];
  const fake = fakeVscode({ command: ["/venv/bin/edsconv", "lsp"] });
  const LanguageClient = fakeClient(started, []);
  const extension = loadExtension({ vscode: fake.vscode, "vscode-languageclient/node": { LanguageClient } });
  await extension.activate({ subscriptions: [] });
  assert.strictEqual(started.length, 1);
  assert.deepStrictEqual(started[0].serverOptions, { command: "/venv/bin/edsconv", args: ["lsp"] });
  // no git: or other virtual document: they would duplicate the diagnostics of the file itself
  assert.deepStrictEqual(started[0].clientOptions.documentSelector,
    [{ scheme: "file", language: "eds" }, { scheme: "untitled", language: "eds" }]);
});

test("a changed server setting and the restart command restart the server", async () => {
  const started = [];
  const stopped = [];
  const settings = { command: ["edsconv", "lsp"] };
  const fake = fakeVscode(settings);
  const LanguageClient = fakeClient(started, stopped);
  const extension = loadExtension({ vscode: fake.vscode, "vscode-languageclient/node": { LanguageClient } });
  await extension.activate({ subscriptions: [] });
  settings.command = ["/other/venv/bin/edsconv", "lsp"];
  await fake.listeners[0]({ affectsConfiguration: (name) => name === "edsconv.server.command" });
  assert.deepStrictEqual(stopped, [started[0]]);
  assert.strictEqual(started[1].serverOptions.command, "/other/venv/bin/edsconv");
  await fake.listeners[0]({ affectsConfiguration: () => false });  // another setting: nothing happens
  assert.strictEqual(started.length, 2);
  await fake.commands["edsconv.restartServer"]();
  assert.deepStrictEqual(stopped, [started[0], started[1]]);
  assert.strictEqual(started.length, 3);
});

test("a server that cannot start is reported, not thrown", async () => {
  const shown = [];
  class LanguageClient {
    async start() { throw new Error("spawn edsconv ENOENT"); }
    dispose() {}
  }
  const { vscode } = fakeVscode({ command: ["edsconv", "lsp"] }, shown);
  const extension = loadExtension({ vscode, "vscode-languageclient/node": { LanguageClient } });
  await extension.activate({ subscriptions: [] });
  assert.strictEqual(shown.length, 1);
  assert.match(shown[0], /pip install 'edsconv\[lsp\]'.*ENOENT/);
});

test("the palette commands run the server's commands on the active EDS document", async () => {
  const shown = [];
  const requests = [];
  const editor = { document: { languageId: "eds", uri: { toString: () => "file:///x/device.eds" } } };
  const fake = fakeVscode({ command: ["edsconv", "lsp"], editor }, shown);
  class LanguageClient {
    async start() {}
    async sendRequest(method, params) {
      requests.push([method, params]);
      return params.command === "edsconv.showDevice" ? { text: "Device\n", document: {} } : 2;
    }
    dispose() {}
  }
  const extension = loadExtension({ vscode: fake.vscode, "vscode-languageclient/node": { LanguageClient } });
  await extension.activate({ subscriptions: [] });
  await fake.commands["edsconv.showDeviceBeside"]();
  assert.deepStrictEqual(requests[0], ["workspace/executeCommand",
    { command: "edsconv.showDevice", arguments: ["file:///x/device.eds"] }]);
  assert.deepStrictEqual(shown[0], { document: { content: "Device\n", language: "plaintext" },
    options: { viewColumn: -2, preview: true } });
  assert.strictEqual(await fake.commands["edsconv.fixAllInActive"](), 2);
  await fake.commands["edsconv.convertActiveToXml"]();
  assert.deepStrictEqual(requests.map(([, params]) => params.command),
    ["edsconv.showDevice", "edsconv.fixAll", "edsconv.convertToXml"]);
  // the server's own command names stay the language client's: no second registration
  assert.ok(!("edsconv.showDevice" in fake.commands));
});
