// Whether the <dialog> with this id is open (a sidebar opened as a modal).
(id) => { const d = document.getElementById(id); return !!(d && d.open); }
