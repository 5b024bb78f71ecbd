;;; eglot.el --- Emacs and eglot as the client of tests/test_lsp_emacs.py  -*- lexical-binding: t -*-
;; Loaded after the init file docs/editors.md gives: visit $EDSCONV_EMACS_FILE, let eglot start
;; `edsconv lsp' as the config says, wait for the first diagnostics, ask for a hover at
;; $EDSCONV_EMACS_HOVER ("line:character", 0-based), and write the major mode, the diagnostic
;; codes and the hover's kind and first line to $EDSCONV_EMACS_OUT.
(require 'eglot)
(defvar edsconv-received nil "The diagnostics of the first publication.")
(advice-add 'eglot-handle-notification :before
            (lambda (_server method &rest params)
              (when (and (eq method 'textDocument/publishDiagnostics) (null edsconv-received))
                (setq edsconv-received (or (plist-get params :diagnostics) [])))))
(find-file (getenv "EDSCONV_EMACS_FILE"))
(run-hooks 'post-command-hook)  ; eglot-ensure connects once a command has run
(let ((deadline (+ (float-time) 30)))
  (while (and (null edsconv-received) (< (float-time) deadline))
    (accept-process-output nil 0.1)))
(unless edsconv-received
  (message "no diagnostics within 30 s (mode %s)" major-mode)
  (kill-emacs 3))
(let* ((where (split-string (getenv "EDSCONV_EMACS_HOVER") ":"))
       (hover (jsonrpc-request (eglot-current-server) :textDocument/hover
                               (list :textDocument (eglot--TextDocumentIdentifier)
                                     :position (list :line (string-to-number (car where))
                                                     :character (string-to-number (cadr where))))))
       (contents (plist-get hover :contents))
       (mode major-mode))
  (with-temp-file (getenv "EDSCONV_EMACS_OUT")
    (insert (format "%s\n" mode)
            (mapconcat (lambda (d) (format "%s" (plist-get d :code))) edsconv-received ",") "\n"
            (format "%s\n" (plist-get contents :kind))
            (car (split-string (plist-get contents :value) "\n")) "\n")))
(kill-emacs 0)
