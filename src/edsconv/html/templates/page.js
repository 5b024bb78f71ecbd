// Sorting and filtering of the parameter tables, the bit maps' full hover; the content reads the same without this script.
"use strict";
(function () {
  const collator = new Intl.Collator(undefined, {numeric: true, sensitivity: "base"});
  function sortBy(table, column, header) {
    const body = table.tBodies[0];
    const ascending = header.getAttribute("aria-sort") !== "ascending";
    for (const th of table.tHead.rows[0].cells) th.removeAttribute("aria-sort");
    header.setAttribute("aria-sort", ascending ? "ascending" : "descending");
    const rows = Array.from(body.rows);
    const keys = new Map(rows.map((row) => [row, row.cells[column].textContent.trim()]));
    rows.sort((a, b) => {
      const x = keys.get(a), y = keys.get(b), nx = Number(x), ny = Number(y);
      const order = x !== "" && y !== "" && !isNaN(nx) && !isNaN(ny) ? nx - ny : collator.compare(x, y);
      return ascending ? order : -order;
    });
    body.append(...rows);
  }
  for (const table of document.querySelectorAll("table[data-sortable]")) {
    Array.from(table.tHead.rows[0].cells).forEach((th, column) => {
      const button = document.createElement("button");
      button.type = "button";
      button.textContent = th.textContent;
      button.title = "Sort by " + th.textContent;
      th.textContent = "";
      th.append(button);
      button.addEventListener("click", () => sortBy(table, column, th));
    });
  }
  for (const input of document.querySelectorAll("input[data-filter]")) {
    const table = document.getElementById(input.dataset.filter);
    const output = input.parentElement.parentElement.querySelector("output");
    const rows = Array.from(table.tBodies[0].rows);
    const texts = rows.map((row) => row.textContent.toLowerCase());
    input.parentElement.parentElement.hidden = false;
    input.addEventListener("input", () => {
      const words = input.value.toLowerCase().split(/\s+/).filter(Boolean);
      let shown = 0;
      rows.forEach((row, index) => {
        const match = words.every((word) => texts[index].includes(word));
        row.hidden = !match;
        if (match) shown += 1;
      });
      output.textContent = words.length ? shown + " of " + rows.length + " shown" : "";
    });
  }
  // A block of a bit map links to its parameter's row, which holds what its short hover leaves out: the
  // first hover adds the row's name (unless the title has it), type, range, default, units and help.
  document.addEventListener("mouseover", (event) => {
    const block = event.target.closest && event.target.closest(".m>a");
    const row = block && !block.dataset.full && document.getElementById(block.getAttribute("href").slice(1));
    if (!row || !row.cells || row.cells.length < 7) return;
    const [, name, type, value, range, units, help] = Array.from(row.cells, (cell) => cell.textContent);
    const title = block.querySelector("title");
    block.dataset.full = "";
    const said = title.textContent.includes(name) ? title.textContent : title.textContent.replace(",", " " + name + ",");
    title.textContent = said +
      "\n" + type + "; range " + range + "; default " + value + (units ? " " + units : "") + (help ? "\n" + help : "");
  });
  // A printed page shows what the collapsed parts hold.
  window.addEventListener("beforeprint", () => {
    for (const details of document.querySelectorAll("details:not([open])")) {
      details.open = true;
      details.dataset.printOpened = "";
    }
  });
  window.addEventListener("afterprint", () => {
    for (const details of document.querySelectorAll("details[data-print-opened]")) {
      details.open = false;
      delete details.dataset.printOpened;
    }
  });
})();
