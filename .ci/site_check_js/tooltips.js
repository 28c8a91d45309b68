// How many tooltips are on screen.
() => [...document.querySelectorAll('.tooltip.show')].length
