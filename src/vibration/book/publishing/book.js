/* The book's own script on top of sphinx-book-theme. No URLs.
   A displayed equation wider than the column scrolls sideways in its own box (book.css): while it does, it is a
   tab stop, so a keyboard can scroll it too (the theme does the same for wide tables, code and outputs). */
(() => {
  const mark = () => {
    document.querySelectorAll('math[display="block"]').forEach((m) => {
      if (m.scrollWidth > m.clientWidth + 1) m.tabIndex = 0;
      else m.removeAttribute("tabindex");
    });
  };
  let pending = null;
  const later = () => { clearTimeout(pending); pending = setTimeout(mark, 200); };
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", mark);
  else mark();
  window.addEventListener("load", mark);
  window.addEventListener("resize", later);
})();
